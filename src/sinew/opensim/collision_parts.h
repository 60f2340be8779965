// The collision model of a parse as shapes to draw (viz::CollisionPart): the seed's cylinders,
// OpenSim's ContactSphere and ContactHalfSpace, the environment.
#pragma once

#include <sinew/contact/collision_model.h>
#include <sinew/viz/collision_parts.h>

#include <vector>

namespace sinew::opensim {

/// Every shape of `model` (spec body indices), for viz::AddCollisionParts or
/// viz::ExportOptions::collision_parts.
std::vector<viz::CollisionPart> CollisionPartsOf(const contact::CollisionModel& model);

}  // namespace sinew::opensim

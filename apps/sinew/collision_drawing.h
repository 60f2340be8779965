// `--collision` of `sinew export` and `sinew render`: the collision shapes the seed's collision
// system would give the model (as `simulate --collision --export` draws them).
#pragma once

#include <sinew/model/model_spec.h>
#include <sinew/viz/collision_parts.h>

#include <string>
#include <vector>

namespace sinew::cli {

/// The collision shapes of `spec` (the seed's cylinders and the contact geometry that
/// collides), in spec body indices, built by parsing it with collision enabled (ContactMesh files
/// searched in `geometry_dirs` too, --geometry-dir). Throws sinew::Error as parsing does.
std::vector<viz::CollisionPart> ModelCollisionParts(const model::ModelSpec& spec,
                                                    const std::vector<std::string>& geometry_dirs);

}  // namespace sinew::cli

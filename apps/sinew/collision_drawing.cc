#include <sinew/engine/system.h>
#include <sinew/opensim/collision_parts.h>
#include <sinew/opensim/parser.h>

#include "apps/sinew/collision_drawing.h"

namespace sinew::cli {

std::vector<viz::CollisionPart> ModelCollisionParts(const model::ModelSpec& spec) {
  opensim::OpenSimParser parser;
  parser.EnableCollision();
  engine::System system(spec.gravity);
  parser.ParseSpec(system, spec);
  return opensim::CollisionPartsOf(parser.GetCollisionModel());
}

}  // namespace sinew::cli

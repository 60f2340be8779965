#include "apps/sinew/collision_drawing.h"

#include <sinew/engine/system.h>
#include <sinew/opensim/collision_parts.h>
#include <sinew/opensim/parser.h>

namespace sinew::cli {

std::vector<viz::CollisionPart> ModelCollisionParts(const model::ModelSpec& spec,
                                                    const std::vector<std::string>& geometry_dirs) {
  opensim::OpenSimParser parser;
  parser.EnableCollision();
  for (const std::string& dir : geometry_dirs) parser.AddGeometryDir(dir);
  engine::System system(spec.gravity);
  parser.ParseSpec(system, spec);
  return opensim::CollisionPartsOf(parser.GetCollisionModel());
}

}  // namespace sinew::cli

// Builders of OpenSim's ExpressionBasedCoordinateForce and ExpressionBasedPointToPointForce.
#include <sinew/forces/expression_based_forces.h>
#include <sinew/model/element_values.h>
#include <sinew/opensim/internal/force_registry.h>

namespace sinew::opensim::internal {

std::shared_ptr<engine::ForceElement> BuildExpressionBasedCoordinateForce(
    const ForceBuildInput& in) {
  const int c = SpecCoordinate(in);
  return std::make_shared<forces::ExpressionBasedCoordinateForce>(
      in.force.name, in.coordinate_map[c], ParseExpression(in, "expression", "0.0", {"q", "qdot"}));
}

std::shared_ptr<engine::ForceElement> BuildExpressionBasedPointToPointForce(
    const ForceBuildInput& in) {
  // OpenSim names the bodies by name or path in `body1`/`body2` (not sockets).
  const PointsOnBodies p = MapPointsOnBodies(in);
  return std::make_shared<forces::ExpressionBasedPointToPointForce>(
      in.force.name, p.body1, p.point1, p.body2, p.point2,
      ParseExpression(in, "expression", "0.0", {"d", "ddot"}));
}

}  // namespace sinew::opensim::internal

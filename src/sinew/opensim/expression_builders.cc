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
  const model::ElementValues& v = in.values;
  // OpenSim names the bodies by name or path in `body1`/`body2` (not sockets).
  const std::string body1 = v.FirstString({"body1", "socket_body1"}).value_or("");
  const std::string body2 = v.FirstString({"body2", "socket_body2"}).value_or("");
  return std::make_shared<forces::ExpressionBasedPointToPointForce>(
      in.force.name, MapBody(in.spec, v, body1, in.body_map, "body1"),
      v.Vector3("point1", Vec3::Zero()), MapBody(in.spec, v, body2, in.body_map, "body2"),
      v.Vector3("point2", Vec3::Zero()), ParseExpression(in, "expression", "0.0", {"d", "ddot"}));
}

}  // namespace sinew::opensim::internal

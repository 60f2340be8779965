#include <sinew/engine/pose.h>
#include <sinew/engine/reactions.h>

namespace sinew::engine {

ConstraintLoads CalcConstraintLoads(const System& system, const State& state,
                                    const Accelerations& accelerations, const KktSolver& kkt,
                                    int k) {
  const Constraint& constraint = *system.constraints()[k];
  const int rows = constraint.NumEquations();
  const int num_bodies = static_cast<int>(constraint.Bodies().size());
  const int num_coordinates = static_cast<int>(constraint.Coordinates().size());
  MatX J(rows, 6 * num_bodies + num_coordinates);
  constraint.CalcJacobian(system, state, J);
  const VecX load = -J.transpose() * accelerations.lambda.segment(kkt.EquationRow(k), rows);
  ConstraintLoads loads;
  for (int i = 0; i < num_bodies; ++i) loads.on_bodies.push_back(load.segment<6>(6 * i));
  loads.on_coordinates = load.tail(num_coordinates);
  return loads;
}

SpatialVec CalcJointReaction(const System& system, const State& state,
                             const Accelerations& accelerations, const KktSolver& kkt, int joint) {
  // Constraint `joint` is the joint's (joints come first); its bodies: parent, then child.
  const SpatialVec on_child_about_Bo =
      CalcConstraintLoads(system, state, accelerations, kkt, joint).on_bodies[1];
  const Joint& j = system.joints()[joint];
  const BodyState& B = state.bodies[j.child];
  const Vec3 p_GM = PoseOf(B) * j.X_BM.p;
  SpatialVec about_M;
  about_M.tail<3>() = on_child_about_Bo.tail<3>();
  about_M.head<3>() = on_child_about_Bo.head<3>() - (p_GM - B.p_GB).cross(about_M.tail<3>());
  return about_M;
}

}  // namespace sinew::engine

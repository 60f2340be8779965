#include <sinew/engine/pose.h>
#include <sinew/engine/reactions.h>

namespace sinew::engine {

SpatialVec CalcJointReaction(const System& system, const State& state,
                             const Accelerations& accelerations, const KktSolver& kkt, int joint) {
  // Constraint k = joint (joints come first); its columns: parent twist, child twist, speeds.
  const Constraint& constraint = *system.constraints()[joint];
  const int rows = constraint.NumEquations();
  const int cols = 12 + static_cast<int>(constraint.Coordinates().size());
  MatX J(rows, cols);
  constraint.CalcJacobian(system, state, J);
  const VecX lambda = accelerations.lambda.segment(kkt.EquationRow(joint), rows);
  const SpatialVec on_child_about_Bo = -J.block(0, 6, rows, 6).transpose() * lambda;
  const Joint& j = system.joints()[joint];
  const BodyState& B = state.bodies[j.child];
  const Vec3 p_GM = PoseOf(B) * j.X_BM.p;
  SpatialVec about_M;
  about_M.tail<3>() = on_child_about_Bo.tail<3>();
  about_M.head<3>() = on_child_about_Bo.head<3>() - (p_GM - B.p_GB).cross(about_M.tail<3>());
  return about_M;
}

}  // namespace sinew::engine

#include <sinew/engine/assemble.h>
#include <sinew/engine/direct_joint.h>
#include <sinew/engine/joint_values.h>
#include <sinew/engine/pose.h>
#include <sinew/engine/projection.h>
#include <sinew/engine/tree_displacement.h>

#include <vector>

namespace sinew::engine {
namespace {

// The new X_FM of every tree joint, one buffer per thread (a System serves many threads).
std::vector<Transform>& JointTransforms() {
  thread_local std::vector<Transform> X_FM;
  return X_FM;
}

// The rotation (rotation vector in G) of body b in dx; zero for ground.
Vec3 BodyRotation(const KktSolver& kkt, const VecX& dx, int b) {
  return b == 0 ? Vec3::Zero() : Vec3(dx.segment<3>(kkt.BodyColumn(b)));
}

// X_FM of direct joint j after the displacement dx, from the poses before it: the relative
// rotation in F (as CalcJointVelocity forms the relative angular velocity) advances the joint's
// own coordinates (the origins of F and M coincide in every direct form).
Transform DisplacedDirectX_FM(const System& system, const KktSolver& kkt, const VecX& dx, int j,
                              const State& state) {
  const Joint& joint = system.joints()[j];
  if (joint.form == JointForm::kWeld) return CalcDirectX_FM(joint.form, {});
  const Mat3 R_FG = (PoseOf(state.bodies[joint.parent]).R * joint.X_PF.R).transpose();
  const Vec3 rotation_F =
      R_FG * (BodyRotation(kkt, dx, joint.child) - BodyRotation(kkt, dx, joint.parent));
  if (joint.form == JointForm::kBall) {
    Transform X_FM = CalcJointTransform(system, state, j);
    X_FM.R = QuatFromRotationVector(rotation_F).toRotationMatrix() * X_FM.R;
    X_FM.p.setZero();
    return X_FM;
  }
  JointValues q(state.q, joint.coordinates);
  if (joint.form == JointForm::kPin) {
    q[0] += rotation_F.z();
  } else {  // Universal: the rotation is da x + db Rx(a) y, and x is perpendicular to Rx(a) y
    const Vec3 second_axis = Eigen::AngleAxisd(q[0], Vec3::UnitX()) * Vec3::UnitY();
    q[1] += rotation_F.dot(second_axis);
    q[0] += rotation_F.x();
  }
  return CalcDirectX_FM(joint.form, q);
}

}  // namespace

void ApplyTreeDisplacement(const System& system, const KktSolver& kkt, const VecX& dx,
                           State& state) {
  // The parameterized joints' coordinates (loop joints' too: they are integrated alike).
  AdvanceIntegratedCoordinates(system, kkt, dx, state);
  // Every tree joint's new X_FM, while all bodies are still where they were.
  std::vector<Transform>& X_FM = JointTransforms();
  X_FM.resize(system.joints().size());
  for (int j : system.tree_order()) {
    const Joint& joint = system.joints()[j];
    X_FM[j] = joint.form == JointForm::kParameterized
                  ? joint.model->CalcX_FM(JointValues(state.q, joint.coordinates))
                  : DisplacedDirectX_FM(system, kkt, dx, j, state);
  }
  // Then each body from its inboard one, outward from ground.
  for (int j : system.tree_order()) PlaceBodyThroughJoint(system, j, X_FM[j], state);
}

}  // namespace sinew::engine

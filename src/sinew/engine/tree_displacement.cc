#include <sinew/engine/direct_joint.h>
#include <sinew/engine/joint_values.h>
#include <sinew/engine/pose.h>
#include <sinew/engine/tree_displacement.h>

#include <vector>

namespace sinew::engine {
namespace {

// The new X_FM of every tree joint, one buffer per thread (a System serves many threads).
std::vector<Transform>& JointTransforms() {
  thread_local std::vector<Transform> X_FM;
  return X_FM;
}

// The displacement of body b's twist columns in dx ([rotation; origin displacement] in G; zero
// for ground).
SpatialVec BodyDisplacement(const KktSolver& kkt, const VecX& dx, int b) {
  return b == 0 ? SpatialVec::Zero() : SpatialVec(dx.segment<6>(kkt.BodyColumn(b)));
}

// X_FM of a direct joint at the poses of `state`.
Transform CurrentX_FM(const Joint& joint, const State& state) {
  return (PoseOf(state.bodies[joint.parent]) * joint.X_PF).Inverse() *
         PoseOf(state.bodies[joint.child]) * joint.X_BM;
}

// X_FM of a direct joint after the displacement dx, from the poses before it: the relative
// displacement [rotation; translation of M's origin] in F (as CalcJointVelocity forms the
// relative twist) advances the joint's own coordinates.
Transform DisplacedDirectX_FM(const KktSolver& kkt, const VecX& dx, const Joint& joint,
                              const State& state) {
  if (joint.form == JointForm::kWeld) return CalcDirectX_FM(joint.form, {});
  const BodyState& P = state.bodies[joint.parent];
  const SpatialVec d_P = BodyDisplacement(kkt, dx, joint.parent);
  const SpatialVec d_B = BodyDisplacement(kkt, dx, joint.child);
  const Mat3 R_FG = (PoseOf(P).R * joint.X_PF.R).transpose();
  const Vec3 rotation_F = R_FG * (d_B.head<3>() - d_P.head<3>());
  JointValues q(state.q, joint.coordinates);
  switch (joint.form) {
    case JointForm::kPin:
      q[0] += rotation_F.z();
      return CalcDirectX_FM(joint.form, q);
    case JointForm::kUniversal: {
      // The rotation is da x + db Rx(a) y, and x is perpendicular to Rx(a) y.
      const Vec3 second_axis = Eigen::AngleAxisd(q[0], Vec3::UnitX()) * Vec3::UnitY();
      q[1] += rotation_F.dot(second_axis);
      q[0] += rotation_F.x();
      return CalcDirectX_FM(joint.form, q);
    }
    case JointForm::kBall: {
      Transform X_FM = CurrentX_FM(joint, state);
      X_FM.R = QuatFromRotationVector(rotation_F).toRotationMatrix() * X_FM.R;
      X_FM.p.setZero();
      return X_FM;
    }
    default:
      break;
  }
  return CalcDirectX_FM(joint.form, q);
}

void SetPose(const Transform& X_GB, BodyState& body) {
  body.p_GB = X_GB.p;
  body.quat_GB = Quat(X_GB.R).normalized();
}

}  // namespace

void ApplyTreeDisplacement(const System& system, const KktSolver& kkt, const VecX& dx,
                           State& state) {
  // The parameterized joints' coordinates (loop joints' too: they are integrated alike).
  for (const Joint& joint : system.joints()) {
    if (joint.form != JointForm::kParameterized || joint.coordinates.empty()) continue;
    const JointValues q(state.q, joint.coordinates);
    JointValues du(q.size()), dq(q.size());
    for (size_t i = 0; i < q.size(); ++i) du[i] = dx[kkt.SpeedColumn(joint.coordinates[i])];
    joint.model->CalcQDot(q, du, dq);
    for (size_t i = 0; i < q.size(); ++i) state.q[joint.coordinates[i]] += dq[i];
  }
  // Every tree joint's new X_FM, while all bodies are still where they were.
  std::vector<Transform>& X_FM = JointTransforms();
  X_FM.resize(system.joints().size());
  for (int j : system.tree_order()) {
    const Joint& joint = system.joints()[j];
    X_FM[j] = joint.form == JointForm::kParameterized
                  ? joint.model->CalcX_FM(JointValues(state.q, joint.coordinates))
                  : DisplacedDirectX_FM(kkt, dx, joint, state);
  }
  // Then each body from its inboard one, outward from ground.
  for (int j : system.tree_order()) {
    const Joint& joint = system.joints()[j];
    if (!system.IsReversed(j)) {
      const Transform X_GF = PoseOf(state.bodies[joint.parent]) * joint.X_PF;
      SetPose(X_GF * X_FM[j] * joint.X_BM.Inverse(), state.bodies[joint.child]);
    } else {
      const Transform X_GM = PoseOf(state.bodies[joint.child]) * joint.X_BM;
      SetPose(X_GM * X_FM[j].Inverse() * joint.X_PF.Inverse(), state.bodies[joint.parent]);
    }
  }
}

void CalcPositionErrorsAfterTreeDisplacement(const System& system, const State& state,
                                             VecX& phi) {
  const auto& constraints = system.constraints();
  int n = 0;
  for (const auto& c : constraints) n += c->NumEquations();
  phi.resize(n);
  int row = 0;
  for (size_t k = 0; k < constraints.size(); ++k) {
    const int m = constraints[k]->NumEquations();
    if (system.HeldByTreePlacement(static_cast<int>(k))) {
      phi.segment(row, m).setZero();
    } else {
      constraints[k]->CalcPositionError(system, state, phi.segment(row, m));
    }
    row += m;
  }
}

}  // namespace sinew::engine

#include <sinew/engine/frame_constraint.h>
#include <sinew/engine/joint_constraints.h>
#include <sinew/engine/joint_values.h>
#include <sinew/engine/pose.h>
#include <sinew/engine/state.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace sinew::engine {
namespace {

// inverse(X_GF) * X_GM = X_FM(q), six rows in F: [rotation; translation].
class ParameterizedJointConstraint final : public Constraint {
 public:
  explicit ParameterizedJointConstraint(const Joint& joint)
      : joint_(joint), quat_PF_(joint.X_PF.R), quat_BM_(joint.X_BM.R) {
    quat_PF_.normalize();
    quat_BM_.normalize();
  }

  std::string name() const override { return joint_.name; }
  int NumEquations() const override { return 6; }
  std::vector<int> Bodies() const override { return {joint_.parent, joint_.child}; }
  std::vector<int> Coordinates() const override { return joint_.coordinates; }

  void CalcPositionError(const System&, const State& state, Eigen::Ref<VecX> phi) const override {
    // The frames composed as unit quaternions (cheaper than composing rotation matrices; the
    // same rotations to round-off).
    const BodyState& P = state.bodies[joint_.parent];
    const BodyState& B = state.bodies[joint_.child];
    const Quat quat_GP = P.quat_GB.normalized(), quat_GB = B.quat_GB.normalized();
    const Quat quat_FG = (quat_GP * quat_PF_).conjugate();
    const Vec3 p_GF = P.p_GB + quat_GP * joint_.X_PF.p;
    const Vec3 p_GM = B.p_GB + quat_GB * joint_.X_BM.p;
    const Quat quat_FM_actual = quat_FG * (quat_GB * quat_BM_);
    const Transform X_FM = joint_.model->CalcX_FM(JointValues(state.q, joint_.coordinates));
    // Rotation vector of R_FM_actual * R_FM(q)^T.
    const Eigen::AngleAxisd error(quat_FM_actual * Quat(X_FM.R).conjugate());
    phi.head<3>() = error.axis() * error.angle();
    phi.tail<3>() = quat_FG * (p_GM - p_GF) - X_FM.p;
  }

  void CalcJacobian(const System&, const State& state, Eigen::Ref<MatX> J) const override {
    // Only R_GF and the origins are needed: R_GF from the composed unit quaternions, and
    // r_BM = R_GB p_BM without forming R_GB.
    const BodyState& P = state.bodies[joint_.parent];
    const BodyState& B = state.bodies[joint_.child];
    const Quat quat_GP = P.quat_GB.normalized();
    const Mat3 R_GF = (quat_GP * quat_PF_).toRotationMatrix();
    const Vec3 r_BM = B.quat_GB.normalized() * joint_.X_BM.p;
    const Vec3 d = B.p_GB + r_BM - P.p_GB;
    const Mat3 Rt = R_GF.transpose();
    // Parent twist columns 0..5, child 6..11, then the joint speeds. Row i of Rt [v]x is
    // (R_GF.col(i) x v)^T.
    J.block<3, 3>(0, 0) = -Rt;
    J.block<3, 3>(0, 3).setZero();
    J.block<3, 3>(3, 3) = -Rt;
    J.block<3, 3>(0, 6) = Rt;
    J.block<3, 3>(0, 9).setZero();
    J.block<3, 3>(3, 9) = Rt;
    for (int i = 0; i < 3; ++i) {
      J.block<1, 3>(3 + i, 0) = R_GF.col(i).cross(d).transpose();
      J.block<1, 3>(3 + i, 6) = -R_GF.col(i).cross(r_BM).transpose();
    }
    const int n = static_cast<int>(joint_.coordinates.size());
    if (n > 0) J.rightCols(n) = -joint_.model->CalcH_FM(JointValues(state.q, joint_.coordinates));
  }

  void CalcAccelerationRhs(const System&, const State& state, Eigen::Ref<VecX> b) const override {
    const BodyState& P = state.bodies[joint_.parent];
    const BodyState& B = state.bodies[joint_.child];
    // R_FG as a quaternion, and the offsets (as in CalcJacobian).
    const Quat quat_FG = (P.quat_GB.normalized() * quat_PF_).conjugate();
    const Vec3 r_BM = B.quat_GB.normalized() * joint_.X_BM.p;
    const Vec3 d = B.p_GB + r_BM - P.p_GB;
    const Vec3 v_M = B.v_GB + B.w_GB.cross(r_BM);
    const Vec3 d_dot = v_M - P.v_GB;
    const Vec3 y = d_dot - P.w_GB.cross(d);
    SpatialVec bias;
    bias.head<3>() = -(quat_FG * P.w_GB.cross(B.w_GB - P.w_GB));
    bias.tail<3>() =
        quat_FG * (B.w_GB.cross(B.w_GB.cross(r_BM)) - P.w_GB.cross(d_dot) - P.w_GB.cross(y));
    SpatialVec hdot_u = SpatialVec::Zero();
    if (!joint_.coordinates.empty()) {
      hdot_u = joint_.model->CalcHDotU(JointValues(state.q, joint_.coordinates),
                                       JointValues(state.u, joint_.coordinates));
    }
    b = hdot_u - bias;
  }

 private:
  Joint joint_;
  Quat quat_PF_, quat_BM_;  // the rotations of joint_.X_PF and joint_.X_BM
};

// q_i - f(t) = 0 on a coordinate of a parameterized joint. Velocity: (N(q) u)_i = f'(t);
// acceleration: (N udot)_i = f''(t) - (Ndot u)_i, Ndot u by a central difference of N along
// qdot (skipped where the joint model says qdot = u, the usual case: then N is the identity
// and Ndot u is zero; Ball/Free rotations are not).
class CoordinateMotionConstraint final : public Constraint {
 public:
  CoordinateMotionConstraint(const Joint& joint, int coordinate, const Coordinate& c)
      : joint_(joint), coordinate_(coordinate), spec_(c) {}

  std::string name() const override { return spec_.name; }
  int NumEquations() const override { return 1; }
  std::vector<int> Bodies() const override { return {}; }
  std::vector<int> Coordinates() const override { return joint_.coordinates; }

  void CalcPositionError(const System&, const State& state, Eigen::Ref<VecX> phi) const override {
    phi[0] = state.q[coordinate_] - Value(state.t, 0);
  }
  void CalcJacobian(const System&, const State& state, Eigen::Ref<MatX> J) const override {
    if (joint_.model->QDotIsU()) {
      J.setZero();
      J(0, spec_.index_in_joint) = 1.0;
      return;
    }
    const JointValues q(state.q, joint_.coordinates);
    JointValues u(q.size()), qdot(q.size());
    for (size_t k = 0; k < q.size(); ++k) {
      u[k] = 1.0;
      joint_.model->CalcQDot(q, u, qdot);
      J(0, static_cast<int>(k)) = qdot[spec_.index_in_joint];
      u[k] = 0.0;
    }
  }
  void CalcVelocityRhs(const System&, const State& state, Eigen::Ref<VecX> c) const override {
    c[0] = Value(state.t, 1);
  }
  void CalcAccelerationRhs(const System&, const State& state, Eigen::Ref<VecX> b) const override {
    if (joint_.model->QDotIsU()) {  // N is the identity: Ndot u = 0
      b[0] = Value(state.t, 2);
      return;
    }
    const JointValues q(state.q, joint_.coordinates), u(state.u, joint_.coordinates);
    const size_t n = q.size();
    JointValues qdot(n), q_plus(n), q_minus(n), a(n), c(n);
    joint_.model->CalcQDot(q, u, qdot);
    double speed = 0.0;
    for (size_t k = 0; k < n; ++k) speed = std::max(speed, std::abs(qdot[k]));
    const double delta = 1e-5 / std::max(1.0, speed);
    for (size_t k = 0; k < n; ++k) {
      q_plus[k] = q[k] + delta * qdot[k];
      q_minus[k] = q[k] - delta * qdot[k];
    }
    joint_.model->CalcQDot(q_plus, u, a);
    joint_.model->CalcQDot(q_minus, u, c);
    const int i = spec_.index_in_joint;
    b[0] = Value(state.t, 2) - (a[i] - c[i]) / (2 * delta);
  }

 private:
  double Value(double t, int order) const {
    if (spec_.motion == CoordinateMotion::kPrescribed && spec_.prescribed) {
      return order == 0 ? spec_.prescribed->Calc(t) : spec_.prescribed->CalcDerivative(t, order);
    }
    return order == 0 ? spec_.default_value : 0.0;
  }
  Joint joint_;
  int coordinate_;
  Coordinate spec_;
};

// The frame equations of a direct joint form (a ball joint keeps only the origins together).
FrameConstraintKind FrameKindOf(JointForm form) {
  switch (form) {
    case JointForm::kPin:
      return FrameConstraintKind::kPin;
    case JointForm::kUniversal:
      return FrameConstraintKind::kUniversal;
    case JointForm::kWeld:
      return FrameConstraintKind::kWeld;
    default:
      return FrameConstraintKind::kPoint;
  }
}

}  // namespace

std::shared_ptr<const Constraint> MakeJointConstraint(const System& system, int joint_index) {
  const Joint& joint = system.joints()[joint_index];
  if (joint.form == JointForm::kParameterized) {
    return std::make_shared<ParameterizedJointConstraint>(joint);
  }
  return std::make_shared<FrameConstraint>(joint.name, joint.parent, joint.X_PF, joint.child,
                                           joint.X_BM, FrameKindOf(joint.form));
}

std::shared_ptr<const Constraint> MakeCoordinateMotionConstraint(const System& system,
                                                                 int coordinate) {
  const Coordinate& c = system.coordinates()[coordinate];
  return std::make_shared<CoordinateMotionConstraint>(system.joints()[c.joint], coordinate, c);
}

}  // namespace sinew::engine

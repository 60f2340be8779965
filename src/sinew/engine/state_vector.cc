#include <sinew/engine/assemble.h>
#include <sinew/engine/joint_values.h>
#include <sinew/engine/pose.h>
#include <sinew/engine/state_vector.h>

#include <cmath>
#include <limits>

namespace sinew::engine {

StateVector::StateVector(const System& system, const KktSolver& kkt) : system_(system), kkt_(kkt) {
  nb_ = system.num_bodies() - 1;
  np_ = 7 * nb_ + system.num_integrated();
  nv_ = kkt.num_velocities();
  nz_ = system.num_state_variables();
}

VecX StateVector::Pack(const State& state) const {
  VecX y(size());
  PackInto(state, y);
  return y;
}

void StateVector::PackInto(const State& state, Eigen::Ref<VecX> y) const {
  for (int b = 1; b <= nb_; ++b) {
    const BodyState& s = state.bodies[b];
    y.segment<3>(7 * (b - 1)) = s.p_GB;
    y.segment<4>(7 * (b - 1) + 3) << s.quat_GB.w(), s.quat_GB.x(), s.quat_GB.y(), s.quat_GB.z();
  }
  for (int c = 0; c < system_.num_coordinates(); ++c) {
    if (system_.IsIntegrated(c)) y[7 * nb_ + system_.SpeedIndex(c)] = state.q[c];
  }
  GatherVelocities(system_, kkt_, state, y.segment(np_, nv_));
  y.tail(nz_) = state.z;
}

void StateVector::Unpack(Eigen::Ref<const VecX> y, double t, State& state) const {
  state.t = t;
  for (int b = 1; b <= nb_; ++b) {
    BodyState& s = state.bodies[b];
    s.p_GB = y.segment<3>(7 * (b - 1));
    const auto qv = y.segment<4>(7 * (b - 1) + 3);
    // A quaternion that is already unit to rounding is kept bit for bit: normalizing it again
    // could move its last bits, and a state packed and unpacked must stay the same positions
    // (the KKT factorization made at them is then reused).
    const Quat quat(qv[0], qv[1], qv[2], qv[3]);
    const double drift = std::abs(quat.squaredNorm() - 1.0);
    s.quat_GB = drift <= 4.0 * std::numeric_limits<double>::epsilon() ? quat : quat.normalized();
  }
  for (int c = 0; c < system_.num_coordinates(); ++c) {
    if (system_.IsIntegrated(c)) state.q[c] = y[7 * nb_ + system_.SpeedIndex(c)];
  }
  ScatterVelocities(system_, kkt_, y.segment(np_, nv_), state);
  state.z = y.tail(nz_);
  UpdateDirectCoordinates(system_, state);
}

void StateVector::Derivative(Eigen::Ref<const VecX> y, const State& state,
                             Eigen::Ref<const VecX> vdot, Eigen::Ref<const VecX> zdot,
                             Eigen::Ref<VecX> yd) const {
  for (int b = 1; b <= nb_; ++b) {
    const BodyState& s = state.bodies[b];
    yd.segment<3>(7 * (b - 1)) = s.v_GB;
    const auto qv = y.segment<4>(7 * (b - 1) + 3);
    const Quat quat(qv[0], qv[1], qv[2], qv[3]);
    // quat_dot = 1/2 [0, w_G] * quat
    const Quat wq(0.0, s.w_GB.x(), s.w_GB.y(), s.w_GB.z());
    const Quat qd = wq * quat;
    yd.segment<4>(7 * (b - 1) + 3) << 0.5 * qd.w(), 0.5 * qd.x(), 0.5 * qd.y(), 0.5 * qd.z();
  }
  for (const Joint& joint : system_.joints()) {
    if (joint.form != JointForm::kParameterized || joint.coordinates.empty()) continue;
    const size_t n = joint.coordinates.size();
    const JointValues q(state.q, joint.coordinates), u(state.u, joint.coordinates);
    JointValues qdot(n);
    joint.model->CalcQDot(q, u, qdot);
    for (size_t i = 0; i < n; ++i) {
      yd[7 * nb_ + system_.SpeedIndex(joint.coordinates[i])] = qdot[i];
    }
  }
  yd.segment(np_, nv_) = vdot;
  yd.tail(nz_) = zdot;
}

}  // namespace sinew::engine

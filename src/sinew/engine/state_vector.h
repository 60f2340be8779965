// The integrated vector of the error-controlled integrators (rk45, cvode):
// y = [positions; velocities; z], with per moving body p_GB and quat_GB (w, x, y, z), then the
// integrated q (in speed order); then the KKT velocities; then the auxiliary state variables.
// Quaternions are kept unnormalized in y and normalized when written into a State.
#pragma once

#include <sinew/engine/kkt.h>
#include <sinew/engine/state.h>
#include <sinew/engine/system.h>

namespace sinew::engine {

class StateVector {
 public:
  StateVector(const System& system, const KktSolver& kkt);
  int size() const { return np_ + nv_ + nz_; }
  int num_velocities() const { return nv_; }
  int num_state_variables() const { return nz_; }

  VecX Pack(const State& state) const;
  /// Pack into `y` (of size()).
  void PackInto(const State& state, Eigen::Ref<VecX> y) const;
  /// Writes y into `state` (direct coordinates then read off the poses).
  void Unpack(Eigen::Ref<const VecX> y, double t, State& state) const;
  /// ydot into `yd` (of size()) at the state `state` unpacked from `y`, given the
  /// accelerations `vdot` and the state variables' derivatives `zdot`.
  void Derivative(Eigen::Ref<const VecX> y, const State& state, Eigen::Ref<const VecX> vdot,
                  Eigen::Ref<const VecX> zdot, Eigen::Ref<VecX> yd) const;

 private:
  const System& system_;
  const KktSolver& kkt_;
  int nb_ = 0, np_ = 0, nv_ = 0, nz_ = 0;
};

}  // namespace sinew::engine

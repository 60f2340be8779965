// OpenSim's CoordinateCouplerConstraint as an engine constraint: a dependent coordinate follows a
// function of one or more independent coordinates, q_d = s f(q_1, ..., q_n).
#pragma once

#include <sinew/engine/constraint.h>
#include <sinew/functions/function.h>

#include <string>
#include <vector>

namespace sinew::forces {

/// phi = q_d - s f(q_i) = 0 (one equation; OpenSim writes s f - q_d, the opposite sign, so the
/// multiplier has the opposite sign too). The speeds enter as J = [-s df/dq_i ..., 1] and the
/// acceleration right-hand side is b = -Jdot u = s sum_ij d2f/dq_i dq_j u_i u_j.
///
/// This uses qdot = u for every coupled coordinate, true for coordinates of CustomJoint, Pin,
/// Slider, Universal, Gimbal, Planar, Weld and the translations of Free and the winging of
/// ScapulothoracicJoint, not for Ball, Ellipsoid and the rotations of Free and Scapulothoracic
/// (there u is an angular velocity): builders must refuse couplers on those. Every coordinate
/// must belong to a parameterized joint (System::IsIntegrated).
class CoordinateCouplerConstraint final : public engine::Constraint {
 public:
  /// `independent` and `dependent` are engine coordinate indices; `f` takes
  /// independent.size() arguments. Throws sinew::Error (component `name`) for a null function,
  /// an argument count that does not match, or a coordinate listed twice.
  CoordinateCouplerConstraint(std::string name, std::vector<int> independent, int dependent,
                              functions::FunctionPtr f, double scale_factor);

  std::string name() const override { return name_; }

  int NumEquations() const override { return 1; }
  std::vector<int> Bodies() const override { return {}; }
  /// The independent coordinates, then the dependent one.
  std::vector<int> Coordinates() const override;
  void CalcPositionError(const engine::System& system, const engine::State& state,
                         Eigen::Ref<VecX> phi) const override;
  void CalcJacobian(const engine::System& system, const engine::State& state,
                    Eigen::Ref<MatX> J) const override;
  void CalcAccelerationRhs(const engine::System& system, const engine::State& state,
                           Eigen::Ref<VecX> b) const override;
  /// The function's (of one independent coordinate) on that coordinate.
  std::vector<std::pair<int, double>> Breakpoints() const override;

 private:
  std::string name_;
  std::vector<int> independent_;
  int dependent_;
  functions::FunctionPtr f_;
  double scale_;
};

}  // namespace sinew::forces

// OpenSim's Thelen2003Muscle as a TensionModel: Thelen (2003)'s curves (thelen2003_curves.h),
// first-order activation dynamics, fixed-width pennation, a compliant tendon, and the fiber
// velocity from the force balance along the tendon. State variables: activation and
// fiber_length. docs/muscles.md gives the equations.
#pragma once

#include <sinew/muscles/first_order_activation.h>
#include <sinew/muscles/fixed_width_pennation.h>
#include <sinew/muscles/tension_model.h>
#include <sinew/muscles/thelen2003_curves.h>

namespace sinew::muscles {

/// The properties every OpenSim Muscle has (SI units; OpenSim's defaults).
struct MuscleParameters {
  double max_isometric_force = 1000.0;      ///< N
  double optimal_fiber_length = 0.1;        ///< m
  double tendon_slack_length = 0.2;         ///< m
  double pennation_angle_at_optimal = 0.0;  ///< rad
  double max_contraction_velocity = 10.0;   ///< optimal fiber lengths per second
};

/// A Thelen2003Muscle's properties (OpenSim's names and defaults).
struct Thelen2003Parameters {
  MuscleParameters muscle;
  Thelen2003CurveParameters curves;
  FirstOrderActivation activation;
  double maximum_pennation_angle = 1.4706289056333368;  ///< rad, acos(0.1)
  double default_activation = 0.05;
  double default_fiber_length = 0.1;  ///< m (OpenSim: the optimal fiber length)
};

/// The Thelen 2003 muscle model.
class Thelen2003Muscle final : public TensionModel {
 public:
  /// Throws sinew::Error (message only) for parameters OpenSim refuses.
  explicit Thelen2003Muscle(const Thelen2003Parameters& parameters);

  const Thelen2003Parameters& parameters() const { return p_; }
  const FixedWidthPennation& pennation() const { return pennation_; }

  /// {"activation", "fiber_length"}.
  std::vector<std::string> StateVariableNames() const override;
  void SetDefaultStateVariables(Eigen::Ref<VecX> z) const override;
  MuscleQuantities Calc(Eigen::Ref<const VecX> z, double excitation,
                        const PathKinematics& path) const override;
  void CalcStateVariableDerivatives(Eigen::Ref<const VecX> z, double excitation,
                                    const PathKinematics& path, const MuscleQuantities& quantities,
                                    Eigen::Ref<VecX> zdot) const override;
  /// Fiber length at which the fiber force along the tendon equals the tendon force, at the
  /// activation in z[0], with the lengthening speed shared between fiber and tendon by their
  /// stiffnesses as OpenSim's Thelen2003Muscle::initMuscleState shares it. When even the
  /// shortest fiber pulls harder than the tendon, the fiber is set to its minimum length (as
  /// OpenSim does, which only warns) and the status says so.
  EquilibriumStatus Equilibrate(const PathKinematics& path, const std::string& component,
                                Eigen::Ref<VecX> z) const override;

 private:
  // (fiber force along the tendon - tendon force) / max_isometric_force at fiber length lce,
  // activation a and force-velocity multiplier fv, and its derivative with respect to lce.
  double EquilibriumError(double lce, double a, double fv, double length, double* slope) const;

  Thelen2003Parameters p_;
  FixedWidthPennation pennation_;
};

}  // namespace sinew::muscles

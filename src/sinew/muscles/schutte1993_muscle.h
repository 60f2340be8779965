// OpenSim's Schutte1993Muscle_Deprecated (a file's Schutte1993Muscle is the same class: OpenSim
// renames it on load) as a TensionModel: the muscle of SIMM and OpenSim 1.x/2.x, with spline
// curves from the file, activation dynamics in a normalized time, a damped Hill force-velocity
// relation solved for the fiber velocity, and OpenSim's isometric-force iteration for
// equilibrium. docs/muscles.md#schutte1993muscle_deprecated-and-schutte1993muscle.
#pragma once

#include <sinew/functions/function.h>
#include <sinew/muscles/deprecated_muscle_equilibrium.h>
#include <sinew/muscles/tension_model.h>
#include <sinew/muscles/thelen2003_muscle.h>

namespace sinew::muscles {

/// A Schutte1993Muscle_Deprecated's properties (OpenSim's names and defaults).
struct Schutte1993Parameters {
  MuscleParameters muscle;
  double time_scale = 0.1;  ///< s: the unit of the model's normalized time
  double activation1 = 7.667;
  double activation2 = 1.459854;
  double damping = 0.1;                              ///< per normalized fiber velocity
  functions::FunctionPtr tendon_force_length_curve;  ///< tendon strain -> force / Fiso
  functions::FunctionPtr active_force_length_curve;  ///< fiber length / optimal -> multiplier
  /// Fiber length / optimal -> force / Fiso; nullptr when the file does not give it: then
  /// exp(8 (lceN - 1)) / exp(4), as OpenSim uses for a default-valued property.
  functions::FunctionPtr passive_force_length_curve;
};

/// The Schutte 1993 muscle model. State variables: activation, fiber_length (both 0 by
/// default, as OpenSim's deprecated muscles start).
class Schutte1993Muscle final : public TensionModel {
 public:
  /// Missing curves take OpenSim's defaults (simm_muscle_curves.h). Throws sinew::Error
  /// (message only) for parameters that make its equations divide by zero.
  explicit Schutte1993Muscle(Schutte1993Parameters parameters);

  std::vector<std::string> StateVariableNames() const override;
  void SetDefaultStateVariables(Eigen::Ref<VecX> z) const override;
  MuscleQuantities Calc(Eigen::Ref<const VecX> z, double excitation,
                        const PathKinematics& path) const override;
  void CalcStateVariableDerivatives(Eigen::Ref<const VecX> z, double excitation,
                                    const PathKinematics& path, const MuscleQuantities& quantities,
                                    Eigen::Ref<VecX> zdot) const override;
  /// OpenSim's computeIsometricForce (SolveDeprecatedIsometricFiberLength): the fiber length at
  /// which the tendon force and the fiber force along the tendon (IsometricImbalance) agree to
  /// 0.01 N at the activation `z` holds. Throws sinew::Error naming `component` when its 100
  /// iterations end further apart.
  EquilibriumStatus Equilibrate(const PathKinematics& path, const std::string& component,
                                Eigen::Ref<VecX> z) const override;

  const Schutte1993Parameters& parameters() const { return p_; }
  /// Normalized tendon force at tendon strain `strain` (0 below 0).
  double TendonForce(double strain) const;
  /// Normalized passive fiber force at normalized fiber length `lceN`.
  double PassiveForce(double lceN) const;
  /// Active force-length multiplier at `lceN`, not below 0.
  double ActiveForceLength(double lceN) const;
  /// Normalized fiber velocity (optimal fiber lengths per time_scale, lengthening positive) at
  /// activation `a`, active force-length multiplier `fal` and velocity-dependent normalized
  /// force `force` (fiber force / Fiso minus the passive force).
  double FiberVelocity(double a, double fal, double force) const;
  /// da/dt (1/s) at activation `a` and excitation `u`.
  double ActivationRate(double a, double u) const;
  /// Tendon force minus fiber force along the tendon (N) at zero fiber velocity, as OpenSim's
  /// computeIsometricForce measures it (active and passive fiber forces not below 0), for a
  /// fiber of length `fiber_length` in a path of length `path_length` (m).
  double IsometricImbalance(double activation, double fiber_length, double path_length) const;
  /// Pennation angle (rad) of a fiber of length `fiber_length` (m) at constant width.
  double Pennation(double fiber_length) const;

 private:
  DeprecatedMuscleCurves Curves() const;

  Schutte1993Parameters p_;
};

}  // namespace sinew::muscles

// OpenSim's Thelen2003Muscle_Deprecated (the Thelen model as OpenSim 2.x computed it) as a
// TensionModel. OpenSim's own forward-dynamics test results (std_arm26_states.sto,
// std_subject01_walk1_states.sto) were made with it: its test renames Thelen2003Muscle to this
// class before loading the model. It differs from Thelen2003Muscle: activation follows
// (u - a) / tau with the plain time constants and no lower bound; the maximum contraction
// velocity grows with activation from Vmax0 to Vmax; the passive curve is
// exp(Kpe (lceN - 1) / e0) / exp(Kpe) (not 0 at the optimal length), linear beyond 1 + e0; the
// tendon uses the paper's rounded constants (toe strain 0.609 e0, slope 1.712 / e0, toe
// force 0.333333) plus 0.001 (1 + strain) everywhere; the force-velocity relation has a
// damping term; pennation is asin(w / lce) with no minimum fiber length. docs/muscles.md.
#pragma once

#include <sinew/muscles/deprecated_muscle_equilibrium.h>
#include <sinew/muscles/tension_model.h>
#include <sinew/muscles/thelen2003_muscle.h>

namespace sinew::muscles {

/// A Thelen2003Muscle_Deprecated's properties (OpenSim's names and defaults).
struct Thelen2003DeprecatedParameters {
  MuscleParameters muscle;
  double activation_time_constant = 0.01, deactivation_time_constant = 0.04;  ///< s
  double Vmax = 10.0, Vmax0 = 5.0;  ///< optimal fiber lengths per second, at a = 1 and a = 0
  double FmaxTendonStrain = 0.033, FmaxMuscleStrain = 0.6;
  double KshapeActive = 0.5, KshapePassive = 4.0;
  double damping = 0.05, Af = 0.3, Flen = 1.8;
  double default_activation = 0.05;
  double default_fiber_length = 0.1;  ///< m
};

/// The deprecated Thelen 2003 muscle model. State variables: activation, fiber_length.
class Thelen2003MuscleDeprecated final : public TensionModel {
 public:
  /// Throws sinew::Error (message only) for parameters that make its equations divide by zero.
  explicit Thelen2003MuscleDeprecated(const Thelen2003DeprecatedParameters& parameters);

  std::vector<std::string> StateVariableNames() const override;
  void SetDefaultStateVariables(Eigen::Ref<VecX> z) const override;
  MuscleQuantities Calc(Eigen::Ref<const VecX> z, double excitation,
                        const PathKinematics& path) const override;
  void CalcStateVariableDerivatives(Eigen::Ref<const VecX> z, double excitation,
                                    const PathKinematics& path, const MuscleQuantities& quantities,
                                    Eigen::Ref<VecX> zdot) const override;
  /// OpenSim's computeIsometricForce for this class (SolveDeprecatedIsometricFiberLength, the
  /// iteration of Schutte1993Muscle's with this model's curves): the fiber length at which the
  /// tendon force and the fiber force along the tendon (IsometricImbalance) agree to 0.01 N at
  /// the activation `z` holds. Throws sinew::Error naming `component` when its 100 iterations
  /// end further apart.
  EquilibriumStatus Equilibrate(const PathKinematics& path, const std::string& component,
                                Eigen::Ref<VecX> z) const override;

  /// The model's normalized curves (exposed for tests).
  double TendonForce(double strain) const;
  double PassiveForce(double lceN) const;
  /// Active force-length multiplier exp(-(lceN - 1)^2 / KshapeActive).
  double ActiveForceLength(double lceN) const;
  /// Tendon force less fiber force along the tendon (N) at zero fiber velocity, as OpenSim's
  /// computeIsometricForce measures it, for a fiber of length `fiber_length` in a path of
  /// length `path_length` (m).
  double IsometricImbalance(double activation, double fiber_length, double path_length) const;
  /// Normalized fiber velocity (per Vmax) at activation a, active force-length multiplier fal
  /// and the velocity-dependent normalized force.
  double FiberVelocity(double a, double fal, double force) const;

 private:
  DeprecatedMuscleCurves Curves() const;

  Thelen2003DeprecatedParameters p_;
};

}  // namespace sinew::muscles

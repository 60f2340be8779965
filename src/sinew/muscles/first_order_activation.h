// First-order activation dynamics (OpenSim's MuscleFirstOrderActivationDynamicModel, used by
// Thelen2003Muscle): da/dt = (u - a) / tau with tau = tau_act (0.5 + 1.5 a) while the
// excitation u exceeds a, and tau_deact / (0.5 + 1.5 a) otherwise; a clamped into
// [minimum_activation, 1] before use. The excitation itself is not clamped.
#pragma once

namespace sinew::muscles {

/// Time constants in s; activations dimensionless.
struct FirstOrderActivation {
  double activation_time_constant = 0.015;
  double deactivation_time_constant = 0.050;
  double minimum_activation = 0.01;

  /// The activation clamped into [minimum_activation, 1].
  double Clamp(double activation) const;
  /// da/dt at `activation` and `excitation` (1/s).
  double CalcDerivative(double activation, double excitation) const;
};

}  // namespace sinew::muscles

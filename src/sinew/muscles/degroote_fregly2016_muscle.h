// DeGrooteFregly2016Muscle's mathematics as pure functions of (muscle, inputs): its state is the
// activation and the normalized tendon force (not the fiber length); the fiber's length follows
// from the tendon force through the tendon curve's inverse, its velocity from the force-velocity
// curve's inverse (explicit form) or from the tendon force's derivative (implicit form).
#pragma once

#include <sinew/muscles/degroote_fregly2016_curves.h>

#include <optional>
#include <string>

namespace sinew::muscles {

/// The properties of a DeGrooteFregly2016Muscle, with OpenSim's names and defaults (SI).
struct DeGrooteFregly2016Parameters {
  std::string name;  ///< the muscle (name or path), for messages
  double max_isometric_force = 1000.0;
  double optimal_fiber_length = 0.1;
  double tendon_slack_length = 0.2;
  double pennation_angle_at_optimal = 0.0;
  double max_contraction_velocity = 10.0;  ///< optimal fiber lengths per second
  bool ignore_tendon_compliance = false;
  bool ignore_activation_dynamics = false;
  double activation_time_constant = 0.015;    ///< s
  double deactivation_time_constant = 0.060;  ///< s
  double default_activation = 0.5;
  double default_normalized_tendon_force = 0.5;
  double active_force_width_scale = 1.0;
  double fiber_damping = 0.0;
  bool ignore_passive_fiber_force = false;
  double passive_fiber_strain_at_one_norm_force = 0.6;
  double tendon_strain_at_one_norm_force = 0.049;
  /// "explicit" (the state derivative from the force-velocity inverse) or "implicit".
  std::string tendon_compliance_dynamics_mode = "explicit";
  double activation_dynamics_smoothing = 0.1;
};

/// A DeGrooteFregly2016Muscle ready to compute. Throws sinew::Error for properties OpenSim
/// refuses (ReadDeGrooteFregly2016Muscle adds file, line and muscle).
class DeGrooteFregly2016Muscle {
 public:
  explicit DeGrooteFregly2016Muscle(const DeGrooteFregly2016Parameters& parameters);
  const DeGrooteFregly2016Parameters& parameters() const { return p_; }
  const DeGrooteFregly2016Curves& curves() const { return curves_; }
  /// The fiber's constant width optimal_fiber_length sin(pennation_angle_at_optimal), m.
  double fiber_width() const { return width_; }
  bool explicit_tendon_dynamics() const { return explicit_; }

 private:
  DeGrooteFregly2016Parameters p_;
  DeGrooteFregly2016Curves curves_;
  double width_ = 0.0;
  bool explicit_ = true;
};

/// What OpenSim's MuscleLengthInfo, FiberVelocityInfo and MuscleDynamicsInfo hold.
struct DeGrooteFregly2016Dynamics {
  double norm_tendon_length = 1.0;
  double tendon_length = 0.0;
  double fiber_length_along_tendon = 0.0;
  double fiber_length = 0.0;
  double norm_fiber_length = 0.0;
  double cos_pennation = 1.0;
  double sin_pennation = 0.0;
  double pennation_angle = 0.0;
  double active_force_length_multiplier = 0.0;
  double passive_force_length_multiplier = 0.0;
  double force_velocity_multiplier = 1.0;
  double norm_fiber_velocity = 0.0;
  double fiber_velocity = 0.0;
  double fiber_velocity_along_tendon = 0.0;
  double tendon_velocity = 0.0;
  double norm_tendon_velocity = 0.0;
  double pennation_angular_velocity = 0.0;
  double activation = 0.0;
  double active_fiber_force = 0.0;
  double passive_elastic_fiber_force = 0.0;
  double passive_damping_fiber_force = 0.0;
  double passive_fiber_force = 0.0;
  double fiber_force = 0.0;
  double fiber_force_along_tendon = 0.0;
  double norm_tendon_force = 0.0;
  double tendon_force = 0.0;
  double fiber_stiffness = 0.0;
  double fiber_stiffness_along_tendon = 0.0;
  double tendon_stiffness = 0.0;
  /// d(normalized tendon force)/dt: the state's derivative (explicit form) or the given one.
  double norm_tendon_force_derivative = 0.0;
};

/// The muscle at `activation` (not clamped, as in OpenSim), normalized tendon force state
/// `norm_tendon_force` (unused with a rigid tendon), path length and lengthening speed. Without
/// `norm_tendon_force_derivative` the explicit form gives the fiber velocity (and the state's
/// derivative); with it, the implicit form takes the tendon velocity from it. Throws
/// sinew::Error naming the muscle when the explicit form is singular (activation or active
/// force-length multiplier 0) or the inputs are not finite.
DeGrooteFregly2016Dynamics CalcDeGrooteFregly2016Dynamics(
    const DeGrooteFregly2016Muscle& muscle, double activation, double norm_tendon_force,
    double path_length, double path_lengthening_speed,
    std::optional<double> norm_tendon_force_derivative = std::nullopt);

/// The implicit form's residual: normalized tendon force - fiber force along the tendon / Fiso.
double CalcDeGrooteFregly2016EquilibriumResidual(const DeGrooteFregly2016Muscle& muscle,
                                                 double activation, double norm_tendon_force,
                                                 double norm_tendon_force_derivative,
                                                 double path_length, double path_lengthening_speed);

/// OpenSim's computeInitialFiberEquilibrium: the normalized tendon force in [0, 5] that zeroes
/// the implicit residual with a zero tendon force derivative, by bisection to an interval of
/// 1e-10 (at most 100 halvings). Returns 0 with a rigid tendon (no state). Throws sinew::Error
/// naming the muscle when the residual has the same sign at 0 and 5 (no equilibrium there).
double SolveDeGrooteFregly2016Equilibrium(const DeGrooteFregly2016Muscle& muscle, double activation,
                                          double path_length, double path_lengthening_speed);

/// da/dt = (u - a) [ (f + 1/2) / (tau_a (0.5 + 1.5 a)) + (1/2 - f) (0.5 + 1.5 a) / tau_d ] with
/// f = tanh(activation_dynamics_smoothing (u - a)) / 2 (the paper's smoothed switch).
double CalcDeGrooteFregly2016ActivationDerivative(const DeGrooteFregly2016Muscle& muscle,
                                                  double activation, double excitation);

}  // namespace sinew::muscles

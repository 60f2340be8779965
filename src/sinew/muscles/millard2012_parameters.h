// Millard2012EquilibriumMuscle's properties, and the muscle they make: its curves, its
// pennation model and its minimum fiber length, with OpenSim's adjustments for the damped and
// the classic (undamped, compliant tendon) forms (OpenSim's extendFinalizeFromProperties).
#pragma once

#include <sinew/muscles/fixed_width_pennation.h>
#include <sinew/muscles/millard2012_curves.h>
#include <sinew/muscles/smooth_segmented_curve.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace sinew::muscles {

/// The properties of a Millard2012EquilibriumMuscle, with OpenSim's names and defaults (SI).
struct Millard2012Parameters {
  std::string name;                         ///< the muscle (name or path), for messages
  double max_isometric_force = 1000.0;      ///< N
  double optimal_fiber_length = 0.1;        ///< m
  double tendon_slack_length = 0.2;         ///< m
  double pennation_angle_at_optimal = 0.0;  ///< rad
  double max_contraction_velocity = 10.0;   ///< optimal fiber lengths per second
  bool ignore_tendon_compliance = false;
  bool ignore_activation_dynamics = false;
  double fiber_damping = 0.1;  ///< normalized damping; below 0.001 the undamped model is used
  double default_activation = 0.05;
  std::optional<double> default_fiber_length;  ///< m; the optimal fiber length when absent
  double activation_time_constant = 0.010;     ///< s
  double deactivation_time_constant = 0.040;   ///< s
  double minimum_activation = 0.01;
  std::optional<double> min_control;                ///< minimum_activation when absent
  double maximum_pennation_angle = std::acos(0.1);  ///< rad
  ActiveForceLengthCurveParameters active_force_length;
  ForceVelocityCurveParameters force_velocity;
  FiberForceLengthCurveParameters fiber_force_length;
  TendonForceLengthCurveParameters tendon_force_length;
};

/// A Millard2012EquilibriumMuscle ready to compute: the parameters in use and what is built
/// from them once. Immutable, so threads may share one.
class Millard2012Muscle {
 public:
  /// Applies OpenSim's adjustments (listed in adjustments()) and builds the curves. With fiber
  /// damping (>= 0.001) or a rigid tendon: the active-force-length minimum becomes 0 and the
  /// force-velocity slopes at +-vmax become 0. With the classic model (compliant tendon, no
  /// damping): the active-force-length minimum is raised to 0.1 and each slope at vmax to at
  /// least half the slope near vmax, so the force-velocity curve can be inverted. Throws
  /// sinew::Error for properties OpenSim refuses (ReadMillard2012Muscle adds file, line and
  /// muscle to the message).
  explicit Millard2012Muscle(const Millard2012Parameters& parameters);

  /// The parameters in use, after the adjustments.
  const Millard2012Parameters& parameters() const { return p_; }
  /// OpenSim's "Parameter update" messages for what was changed, in its words.
  const std::vector<std::string>& adjustments() const { return adjustments_; }
  /// True when the damped model is used (fiber_damping >= 0.001).
  bool uses_fiber_damping() const { return use_damping_; }

  const SmoothSegmentedCurve& active_force_length() const { return active_force_length_; }
  const SmoothSegmentedCurve& force_velocity() const { return force_velocity_; }
  /// Built with slopes at vmax of half those near vmax (as OpenSim builds it for this muscle).
  const SmoothSegmentedCurve& force_velocity_inverse() const { return force_velocity_inverse_; }
  const SmoothSegmentedCurve& fiber_force_length() const { return fiber_force_length_; }
  const SmoothSegmentedCurve& tendon_force_length() const { return tendon_force_length_; }
  const FixedWidthPennation& pennation() const { return pennation_; }

  /// max(min_norm_active_fiber_length * optimal length, the pennation model's minimum).
  double minimum_fiber_length() const { return minimum_fiber_length_; }
  /// The fiber length a state variable is clamped to: max(length, minimum_fiber_length).
  double ClampFiberLength(double fiber_length) const;
  /// Activation within [minimum_activation, 1].
  double ClampActivation(double activation) const;

 private:
  Millard2012Parameters p_;
  std::vector<std::string> adjustments_;
  bool use_damping_ = true;
  SmoothSegmentedCurve active_force_length_, force_velocity_, force_velocity_inverse_,
      fiber_force_length_, tendon_force_length_;
  FixedWidthPennation pennation_;
  double minimum_fiber_length_ = 0.0;
};

}  // namespace sinew::muscles

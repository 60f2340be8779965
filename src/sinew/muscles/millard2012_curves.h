// Millard2012's muscle curves (OpenSim's ActiveForceLengthCurve, ForceVelocityCurve,
// ForceVelocityInverseCurve, FiberForceLengthCurve, TendonForceLengthCurve,
// FiberCompressiveForceLengthCurve, FiberCompressiveForceCosPennationCurve): each a
// SmoothSegmentedCurve built from its properties as OpenSim's SmoothSegmentedFunctionFactory
// builds it. Lengths are normalized by the optimal fiber length (fibers) or the tendon slack
// length (tendon), velocities by vmax times the optimal fiber length, forces by the maximum
// isometric force. Property names and default values are OpenSim's.
#pragma once

#include <sinew/muscles/smooth_segmented_curve.h>

#include <optional>

namespace sinew::muscles {

/// ActiveForceLengthCurve: 0 (or minimum_value) outside [min, max] active lengths, 1 at
/// normalized length 1 with zero slope, shallow_ascending_slope at the transition.
struct ActiveForceLengthCurveParameters {
  double min_norm_active_fiber_length = 0.47 - 0.0259;
  double transition_norm_fiber_length = 0.73;
  double max_norm_active_fiber_length = 1.8123;
  double shallow_ascending_slope = 0.8616;
  double minimum_value = 0.1;
};
SmoothSegmentedCurve MakeActiveForceLengthCurve(const ActiveForceLengthCurveParameters& p);

/// ForceVelocityCurve: multiplier 0 at normalized velocity -1 (shortening at vmax), 1 at 0,
/// max_eccentric_velocity_force_multiplier at +1, with the given slopes there and near there.
struct ForceVelocityCurveParameters {
  double concentric_slope_at_vmax = 0.0;
  double concentric_slope_near_vmax = 0.25;
  double isometric_slope = 5.0;
  double eccentric_slope_at_vmax = 0.0;
  double eccentric_slope_near_vmax = 0.15;
  double max_eccentric_velocity_force_multiplier = 1.4;
  double concentric_curviness = 0.6;
  double eccentric_curviness = 0.9;
};
SmoothSegmentedCurve MakeForceVelocityCurve(const ForceVelocityCurveParameters& p);

/// ForceVelocityInverseCurve's defaults: those of the ForceVelocityCurve but slopes of 0.1 at
/// +-vmax (the inverse needs nonzero end slopes).
ForceVelocityCurveParameters DefaultForceVelocityInverseCurveParameters();
/// The normalized fiber velocity as a function of the force-velocity multiplier: the same
/// Bezier segments as MakeForceVelocityCurve with x and y exchanged. Throws for end slopes at
/// vmax that are not positive.
SmoothSegmentedCurve MakeForceVelocityInverseCurve(const ForceVelocityCurveParameters& p);

/// FiberForceLengthCurve (passive fiber force): 0 up to 1 + strain_at_zero_force, 1 at
/// 1 + strain_at_one_norm_force. The three optional properties are all given or all absent;
/// absent, OpenSim uses stiffness 2 / (e1 - e0) at one norm force, 0.2 at low force and
/// curviness 0.75.
struct FiberForceLengthCurveParameters {
  double strain_at_zero_force = 0.0;
  double strain_at_one_norm_force = 0.7;
  std::optional<double> stiffness_at_low_force;
  std::optional<double> stiffness_at_one_norm_force;
  std::optional<double> curviness;
};
SmoothSegmentedCurve MakeFiberForceLengthCurve(const FiberForceLengthCurveParameters& p);

/// TendonForceLengthCurve: 0 up to the slack length (normalized length 1), 1 at
/// 1 + strain_at_one_norm_force. Optional properties all given or all absent; absent, OpenSim
/// uses stiffness 1.375 / strain, toe end at force 2/3 and curviness 0.5.
struct TendonForceLengthCurveParameters {
  double strain_at_one_norm_force = 0.049;
  std::optional<double> stiffness_at_one_norm_force;
  std::optional<double> norm_force_at_toe_end;
  std::optional<double> curviness;
};
SmoothSegmentedCurve MakeTendonForceLengthCurve(const TendonForceLengthCurveParameters& p);

/// FiberCompressiveForceLengthCurve: 1 at length 0 falling to 0 at norm_length_at_zero_force.
/// Optional properties both given or both absent (stiffness -2 / length, curviness 0.5).
struct FiberCompressiveForceLengthCurveParameters {
  double norm_length_at_zero_force = 0.5;
  std::optional<double> stiffness_at_zero_length;
  std::optional<double> curviness;
};
SmoothSegmentedCurve MakeFiberCompressiveForceLengthCurve(
    const FiberCompressiveForceLengthCurveParameters& p);

/// FiberCompressiveForceCosPennationCurve, a function of cos(pennation): 1 at cos = 0 falling to
/// 0 at the cosine of engagement_angle_in_degrees. Optional properties both given or both
/// absent (stiffness -2 / cos(engagement angle), curviness 0.1).
struct FiberCompressiveForceCosPennationCurveParameters {
  double engagement_angle_in_degrees = 85.0;
  std::optional<double> stiffness_at_perpendicular;
  std::optional<double> curviness;
};
SmoothSegmentedCurve MakeFiberCompressiveForceCosPennationCurve(
    const FiberCompressiveForceCosPennationCurveParameters& p);

}  // namespace sinew::muscles

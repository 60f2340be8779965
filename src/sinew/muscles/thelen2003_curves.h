// The curves of Thelen (2003), "Adjustment of muscle mechanics model parameters to simulate
// dynamic contractions in older adults", J Biomech Eng 125:70-77, with the constants and the
// extensions OpenSim's Thelen2003Muscle uses (tendon toe region solved exactly, linear
// extrapolation of the force-velocity relation). Dimensionless: lengths normalized by the
// optimal fiber length or the tendon slack length, forces by the maximum isometric force,
// fiber velocity by max_contraction_velocity * optimal_fiber_length.
#pragma once

namespace sinew::muscles {

/// The shape parameters of Thelen2003Muscle (OpenSim's property names and defaults).
struct Thelen2003CurveParameters {
  double FmaxTendonStrain = 0.04;  ///< tendon strain at the maximum isometric force
  double FmaxMuscleStrain = 0.6;   ///< passive fiber strain at the maximum isometric force
  double KshapeActive = 0.45;      ///< width of the Gaussian active force-length curve
  double KshapePassive = 5.0;      ///< exponential shape of the passive force-length curve
  double Af = 0.25;                ///< force-velocity shape factor
  double Flen = 1.4;               ///< maximum normalized lengthening force
  double fv_linear_extrap_threshold = 0.95;  ///< fraction of Flen where fv turns linear
};

/// Active force-length multiplier exp(-(lceN - 1)^2 / KshapeActive) and its derivative.
double ThelenActiveForceLength(const Thelen2003CurveParameters& p, double lceN);
double ThelenActiveForceLengthSlope(const Thelen2003CurveParameters& p, double lceN);

/// Passive force-length multiplier (exp(Kpe (lceN - 1) / e0) - 1) / (exp(Kpe) - 1) above the
/// optimal length, 0 below, and its derivative.
double ThelenPassiveForceLength(const Thelen2003CurveParameters& p, double lceN);
double ThelenPassiveForceLengthSlope(const Thelen2003CurveParameters& p, double lceN);

/// Tendon force-length multiplier of the normalized tendon length: 0 when slack, an
/// exponential toe F_toe (exp(k_toe e / e_toe) - 1) / (exp(k_toe) - 1) up to the toe strain,
/// then linear with the slope that is continuous there (k_toe = 3, F_toe = 0.33, e_toe and
/// the slope from the condition that the force is 1 at FmaxTendonStrain), and its derivative.
double ThelenTendonForceLength(const Thelen2003CurveParameters& p, double tlN);
double ThelenTendonForceLengthSlope(const Thelen2003CurveParameters& p, double tlN);

/// Normalized fiber velocity (lengthening positive) at which the fiber develops the force
/// a*fal*fv = `force` (normalized) at activation a and active force-length multiplier fal:
/// Thelen's inverse force-velocity relation, linear beyond 0 (concentric) and beyond
/// fv_linear_extrap_threshold * Flen (eccentric). And d(velocity)/d(force).
double ThelenFiberVelocity(const Thelen2003CurveParameters& p, double a, double fal, double force);
double ThelenFiberVelocitySlope(const Thelen2003CurveParameters& p, double a, double fal,
                                double force);

/// The force-velocity multiplier fv at normalized fiber velocity `dlceN` (the inverse of
/// ThelenFiberVelocity, by Newton's method), clamped below at 0 as OpenSim does.
double ThelenForceVelocity(const Thelen2003CurveParameters& p, double a, double fal, double dlceN);

}  // namespace sinew::muscles

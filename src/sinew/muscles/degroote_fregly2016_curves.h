// DeGrooteFregly2016Muscle's curves: the closed forms published by De Groote, Kinney, Rao and
// Fregly (2016, Ann Biomed Eng 44:2922, "Evaluation of direct collocation optimal control
// problem formulations for solving the muscle redundancy problem"), with the coefficients of that
// paper and OpenSim's parameterization of the passive and tendon curves by their strains at one
// normalized force. Lengths normalized by the optimal fiber length or the tendon slack length,
// velocities by max_contraction_velocity times the optimal fiber length.
#pragma once

namespace sinew::muscles {

/// The four curves and their derivatives, inverses and integrals.
class DeGrooteFregly2016Curves {
 public:
  /// OpenSim's properties: active_force_width_scale (>= 1), passive_fiber_strain_at_one_norm_force
  /// (> 0), tendon_strain_at_one_norm_force (> 0), ignore_passive_fiber_force. Throws
  /// sinew::Error for values outside those ranges.
  DeGrooteFregly2016Curves(double active_force_width_scale = 1.0,
                           double passive_fiber_strain_at_one_norm_force = 0.6,
                           double tendon_strain_at_one_norm_force = 0.049,
                           bool ignore_passive_fiber_force = false);

  /// The sum of three Gaussian-like terms b1 exp(-(x - b2)^2 / (2 (b3 + b4 x)^2)) at
  /// x = (l~ - 1) / width_scale + 1.
  double ActiveForceLength(double norm_fiber_length) const;
  double ActiveForceLengthDerivative(double norm_fiber_length) const;

  /// d1 ln(d2 v~ + d3 + sqrt((d2 v~ + d3)^2 + 1)) + d4 (an inverse hyperbolic sine).
  static double ForceVelocity(double norm_fiber_velocity);
  static double ForceVelocityDerivative(double norm_fiber_velocity);
  /// (sinh((f - d4) / d1) - d3) / d2, the exact inverse.
  static double ForceVelocityInverse(double force_velocity_multiplier);

  /// (exp(kPE (l~ - 1) / e0) - exp(kPE (0.2 - 1) / e0)) / (exp(kPE) - exp(kPE (0.2 - 1) / e0))
  /// with kPE = 4: 0 at the minimum normalized length 0.2, 1 at 1 + e0 (0 when ignored).
  double PassiveForceLength(double norm_fiber_length) const;
  double PassiveForceLengthDerivative(double norm_fiber_length) const;
  /// Its integral from l~ = 0.2 (the passive elastic energy over Fiso optimal length).
  double PassiveForceLengthIntegral(double norm_fiber_length) const;

  /// c1 exp(kT (l~T - c2)) - c3 with c1 = c3 = 0.2, c2 = 1 and kT = ln((1 + c3) / c1) / eT:
  /// 0 at the slack length, 1 at strain eT. Negative (down to -0.2) below the slack length, as
  /// in the paper and OpenSim.
  double TendonForceLength(double norm_tendon_length) const;
  double TendonForceLengthDerivative(double norm_tendon_length) const;
  /// The normalized tendon length at a normalized tendon force (> -0.2).
  double TendonForceLengthInverse(double norm_tendon_force) const;
  /// Its integral from the length at zero force (the slack length).
  double TendonForceLengthIntegral(double norm_tendon_length) const;
  /// kT.
  double tendon_stiffness_parameter() const { return k_tendon_; }

 private:
  double width_scale_;
  double passive_strain_;
  bool ignore_passive_;
  double k_tendon_;
};

}  // namespace sinew::muscles

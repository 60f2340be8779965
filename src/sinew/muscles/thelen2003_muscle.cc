#include <sinew/common/error.h>
#include <sinew/muscles/thelen2003_muscle.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace sinew::muscles {
namespace {

void Require(bool ok, const std::string& what) {
  if (!ok) throw Error(SourceLocation{}, "", what);
}

}  // namespace

Thelen2003Muscle::Thelen2003Muscle(const Thelen2003Parameters& parameters)
    : p_(parameters),
      pennation_(parameters.muscle.optimal_fiber_length,
                 parameters.muscle.pennation_angle_at_optimal, parameters.maximum_pennation_angle) {
  const Thelen2003CurveParameters& c = p_.curves;
  Require(p_.muscle.max_isometric_force > 0.0, "max_isometric_force must be greater than zero");
  Require(p_.muscle.tendon_slack_length > 0.0, "tendon_slack_length must be greater than zero");
  Require(p_.muscle.max_contraction_velocity > 0.0,
          "max_contraction_velocity must be greater than zero");
  Require(c.FmaxTendonStrain > 0.0, "FmaxTendonStrain must be greater than zero");
  Require(c.FmaxMuscleStrain > 0.0, "FmaxMuscleStrain must be greater than zero");
  Require(c.KshapeActive > 0.0, "KshapeActive must be greater than zero");
  Require(c.KshapePassive > 0.0, "KshapePassive must be greater than zero");
  Require(c.Af > 0.0, "Af must be greater than zero");
  Require(c.Flen > 1.0, "Flen must be greater than 1");
  Require(c.fv_linear_extrap_threshold > 1.0 / c.Flen,
          "fv_linear_extrap_threshold must be greater than 1/Flen");
  Require(p_.activation.minimum_activation >= 0.01,
          "minimum_activation cannot be less than 0.01 (OpenSim's rule)");
  Require(p_.activation.activation_time_constant > 0.0 &&
              p_.activation.deactivation_time_constant > 0.0,
          "activation and deactivation time constants must be greater than zero");
}

std::vector<std::string> Thelen2003Muscle::StateVariableNames() const {
  return {"activation", "fiber_length"};
}

void Thelen2003Muscle::SetDefaultStateVariables(Eigen::Ref<VecX> z) const {
  z[0] = p_.default_activation;
  z[1] = p_.default_fiber_length;
}

MuscleQuantities Thelen2003Muscle::Calc(Eigen::Ref<const VecX> z, double /*excitation*/,
                                        const PathKinematics& path) const {
  const MuscleParameters& m = p_.muscle;
  MuscleQuantities out;
  out.activation = p_.activation.Clamp(z[0]);
  const double a = out.activation;
  const double lce = pennation_.ClampFiberLength(z[1]);
  out.fiber_length = lce;
  out.pennation_angle = pennation_.PennationAngle(lce);
  const double cos_phi = std::cos(out.pennation_angle);
  out.tendon_length = path.length - lce * cos_phi;
  const double lceN = lce / m.optimal_fiber_length;
  const double fse = ThelenTendonForceLength(p_.curves, out.tendon_length / m.tendon_slack_length);
  const double fal = ThelenActiveForceLength(p_.curves, lceN);
  const double fpe = ThelenPassiveForceLength(p_.curves, lceN);
  // The tendon force fixes the active fiber force a fal fv; the force-velocity relation then
  // gives the fiber velocity.
  const double active_normalized = fse / cos_phi - fpe;
  double dlceN = ThelenFiberVelocity(p_.curves, a, fal, active_normalized);
  double fv = active_normalized / (a * fal);
  // At its minimum length a fiber cannot shorten further (OpenSim's isFiberStateClamped).
  const bool clamped = z[1] <= pennation_.minimum_fiber_length() && dlceN <= 0.0;
  if (clamped) {
    dlceN = 0.0;
    fv = 1.0;
  }
  out.fiber_velocity = dlceN * m.max_contraction_velocity * m.optimal_fiber_length;
  out.active_fiber_force = clamped ? 0.0 : a * fal * fv * m.max_isometric_force;
  out.passive_fiber_force = fpe * m.max_isometric_force;
  out.tendon_force = fse * m.max_isometric_force;
  return out;
}

void Thelen2003Muscle::CalcStateVariableDerivatives(Eigen::Ref<const VecX> z, double excitation,
                                                    const PathKinematics& /*path*/,
                                                    const MuscleQuantities& quantities,
                                                    Eigen::Ref<VecX> zdot) const {
  zdot[0] = p_.activation.CalcDerivative(z[0], excitation);
  zdot[1] = quantities.fiber_velocity;
}

double Thelen2003Muscle::EquilibriumError(double lce, double a, double fv, double length,
                                          double* slope) const {
  const MuscleParameters& m = p_.muscle;
  const double ofl = m.optimal_fiber_length, tsl = m.tendon_slack_length;
  const double phi = pennation_.PennationAngle(lce);
  const double cos_phi = std::cos(phi);
  const double lceN = lce / ofl;
  const double tlN = (length - lce * cos_phi) / tsl;
  const double fiber =
      a * ThelenActiveForceLength(p_.curves, lceN) * fv + ThelenPassiveForceLength(p_.curves, lceN);
  const double dfiber = (a * fv * ThelenActiveForceLengthSlope(p_.curves, lceN) +
                         ThelenPassiveForceLengthSlope(p_.curves, lceN)) /
                        ofl;
  // d(cos phi)/dlce = h^2 / (lce^3 cos phi) while the fiber pennates freely; d(lce cos phi)/dlce
  // = 1 / cos phi there, so the tendon shortens by 1 / cos phi per unit of fiber length.
  const double h = pennation_.parallelogram_height();
  const bool free = phi > 0.0 && lce > pennation_.minimum_fiber_length();
  const double dcos = free ? h * h / (lce * lce * lce * cos_phi) : 0.0;
  const double dtendon = free ? -1.0 / cos_phi : -cos_phi;
  *slope = dfiber * cos_phi + fiber * dcos -
           ThelenTendonForceLengthSlope(p_.curves, tlN) * dtendon / tsl;
  return fiber * cos_phi - ThelenTendonForceLength(p_.curves, tlN);
}

EquilibriumStatus Thelen2003Muscle::Equilibrate(const PathKinematics& path,
                                                const std::string& component,
                                                Eigen::Ref<VecX> z) const {
  const MuscleParameters& m = p_.muscle;
  const double a = p_.activation.Clamp(z[0]);
  const double lmin = pennation_.minimum_fiber_length();
  // The root lies between the minimum fiber length and the length at which the tendon is
  // slack (there the tendon pulls nothing and the fiber force is >= 0).
  const double lslack = std::max(lmin, pennation_.FiberLength(path.length, m.tendon_slack_length));
  double fv = 1.0;
  double lce = lslack;
  bool at_minimum = false;
  constexpr int kMaxOuter = 50, kMaxInner = 200;
  for (int outer = 0; outer < kMaxOuter; ++outer) {
    double slope = 0.0;
    at_minimum = EquilibriumError(lmin, a, fv, path.length, &slope) >= 0.0;
    if (at_minimum) {
      lce = lmin;  // even the shortest fiber pulls at least as hard as the tendon
    } else {
      // Newton's method kept inside the bracket [lo, hi] (g(lo) < 0 <= g(hi)), bisecting
      // whenever a step would leave it.
      double lo = lmin, hi = lslack;
      lce = 0.5 * (lo + hi);
      for (int i = 0; i < kMaxInner; ++i) {
        const double g = EquilibriumError(lce, a, fv, path.length, &slope);
        if (g < 0.0)
          lo = lce;
        else
          hi = lce;
        if (std::abs(g) < 1e-13 || hi - lo < 1e-15 * m.optimal_fiber_length) break;
        const double next = lce - g / slope;
        lce = (slope > 0.0 && next > lo && next < hi) ? next : 0.5 * (lo + hi);
      }
    }
    if (path.lengthening_speed == 0.0) break;
    // Share the lengthening speed between tendon and fiber by their stiffnesses along the
    // tendon, then read fv off the force-velocity relation, until fv settles.
    const double phi = pennation_.PennationAngle(lce);
    const double cos_phi = std::cos(phi);
    const double tl = path.length - lce * cos_phi;
    EquilibriumError(lce, a, fv, path.length, &slope);
    const double tendon_stiffness =
        ThelenTendonForceLengthSlope(p_.curves, tl / m.tendon_slack_length) / m.tendon_slack_length;
    // slope = dFmAT/dlce - dFt/dlce, and dFt/dlce = -tendon_stiffness d(lce cos phi)/dlce.
    const bool free = phi > 0.0 && lce > lmin;
    const double fiber_stiffness = slope - tendon_stiffness * (free ? 1.0 / cos_phi : cos_phi);
    const double along = fiber_stiffness * cos_phi;
    const double sum = along + tendon_stiffness;
    const double tendon_speed = (std::abs(sum) > 1e-14 && tl > m.tendon_slack_length)
                                    ? along / sum * path.lengthening_speed
                                    : path.lengthening_speed;
    const double dlceN = (path.lengthening_speed - tendon_speed) * cos_phi /
                         (m.max_contraction_velocity * m.optimal_fiber_length);
    const double fal = ThelenActiveForceLength(p_.curves, lce / m.optimal_fiber_length);
    const double next_fv = ThelenForceVelocity(p_.curves, a, fal, dlceN);
    const bool settled = std::abs(next_fv - fv) < 1e-13;
    fv = next_fv;
    if (settled) break;
  }
  double slope = 0.0;
  const double error = EquilibriumError(lce, a, fv, path.length, &slope);
  if (!std::isfinite(lce) || (!at_minimum && !(std::abs(error) < 1e-8))) {
    throw Error(SourceLocation{}, component,
                "no muscle-tendon equilibrium at musculotendon length " +
                    std::to_string(path.length) + " m, activation " + std::to_string(a) +
                    " (force error " + std::to_string(error * m.max_isometric_force) + " N)");
  }
  z[1] = lce;
  return at_minimum ? EquilibriumStatus::kFiberAtMinimumLength : EquilibriumStatus::kBalanced;
}

}  // namespace sinew::muscles

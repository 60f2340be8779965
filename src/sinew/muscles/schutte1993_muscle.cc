#include <sinew/common/error.h>
#include <sinew/muscles/schutte1993_muscle.h>
#include <sinew/muscles/simm_muscle_curves.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <utility>

namespace sinew::muscles {
namespace {

// OpenSim 2.x's test for "equal" (SimmMacros' ROUNDOFF_ERROR).
constexpr double kRoundoff = 2e-13;

// OpenSim's calcPennation: asin(optimal sin(phi_opt) / length), 0 for a vanishing length,
// pi / 2 once the fiber is no longer than the muscle's width.
double PennationOf(double length, double optimal, double pennation_at_optimal) {
  if (length < std::numeric_limits<double>::epsilon()) return 0.0;
  const double s = optimal * std::sin(pennation_at_optimal) / length;
  if (std::isnan(s) || s <= 0.0) return 0.0;
  return s >= 1.0 ? std::numbers::pi / 2 : std::asin(s);
}

}  // namespace

Schutte1993Muscle::Schutte1993Muscle(Schutte1993Parameters parameters) : p_(std::move(parameters)) {
  auto require = [](bool ok, const char* what) {
    if (!ok) throw Error(SourceLocation{}, "", what);
  };
  require(p_.muscle.optimal_fiber_length > 0.0, "optimal_fiber_length must be greater than zero");
  require(p_.muscle.tendon_slack_length > 0.0, "tendon_slack_length must be greater than zero");
  require(p_.time_scale > 0.0, "time_scale must be greater than zero");
  require(p_.damping > 0.0, "damping must be greater than zero (the fiber velocity divides by it)");
  if (!p_.tendon_force_length_curve)
    p_.tendon_force_length_curve = MakeDefaultTendonForceLengthCurve();
  if (!p_.active_force_length_curve)
    p_.active_force_length_curve = MakeDefaultActiveForceLengthCurve();
}

std::vector<std::string> Schutte1993Muscle::StateVariableNames() const {
  return {"activation", "fiber_length"};
}

void Schutte1993Muscle::SetDefaultStateVariables(Eigen::Ref<VecX> z) const {
  z[0] = 0.0;
  z[1] = 0.0;
}

double Schutte1993Muscle::TendonForce(double strain) const {
  return strain < 0.0 ? 0.0 : p_.tendon_force_length_curve->Calc(strain);
}

double Schutte1993Muscle::PassiveForce(double lceN) const {
  if (!p_.passive_force_length_curve) return std::exp(8.0 * (lceN - 1.0)) / std::exp(4.0);
  return p_.passive_force_length_curve->Calc(lceN);
}

double Schutte1993Muscle::ActiveForceLength(double lceN) const {
  return std::max(p_.active_force_length_curve->Calc(lceN), 0.0);
}

double Schutte1993Muscle::Pennation(double fiber_length) const {
  return PennationOf(fiber_length, p_.muscle.optimal_fiber_length,
                     p_.muscle.pennation_angle_at_optimal);
}

// The roots of Schutte's force-velocity relation with damping d, written for the velocity:
// shortening F = a fal kv (1 + v) / (kv - v) + d v, lengthening
// F = a fal (fmax v + s) / (v + s) + d v with s = slope_k kv / (kv + 1); each a quadratic in v.
double Schutte1993Muscle::FiberVelocity(double a, double fal, double force) const {
  constexpr double kv = 0.15, slope_k = 0.13, fmax = 1.4;
  const double d = p_.damping, fa = a * fal;
  if (force < -d) return force / d;
  if (force < fa) {
    const double c = kv * (force - fa) / d;
    const double b = -kv * (force / kv + fa + d) / d;
    return (-b - std::sqrt(b * b - 4.0 * c)) / 2.0;
  }
  const double s = slope_k * kv / (kv + 1.0);
  const double c = -(s / d) * (force - fa);
  const double b = -(force / d - fmax * fa / d - s);
  return (-b + std::sqrt(b * b - 4.0 * c)) / 2.0;
}

double Schutte1993Muscle::ActivationRate(double a, double u) const {
  const double rate =
      u >= a ? (u - a) * (p_.activation1 * u + p_.activation2) : (u - a) * p_.activation2;
  return rate / p_.time_scale;
}

MuscleQuantities Schutte1993Muscle::Calc(Eigen::Ref<const VecX> z, double /*excitation*/,
                                         const PathKinematics& path) const {
  const MuscleParameters& m = p_.muscle;
  const double ofl = m.optimal_fiber_length, phi0 = m.pennation_angle_at_optimal;
  MuscleQuantities out;
  out.activation = z[0];
  out.fiber_length = z[1];
  const double lceN = z[1] / ofl;
  out.pennation_angle = PennationOf(lceN, 1.0, phi0);
  const double ca = std::cos(out.pennation_angle);
  const double path_norm = path.length / ofl;
  const double tendon_norm = path_norm - lceN * ca;
  out.tendon_length = tendon_norm * ofl;
  const double rest = m.tendon_slack_length / ofl;
  const double tendon = TendonForce((tendon_norm - rest) / rest);
  const double passive = PassiveForce(lceN);
  double velocity = 0.0;  // optimal fiber lengths per time_scale
  if (std::abs(ca) <= kRoundoff) {
    // Fibers at 90 degrees: OpenSim moves them with the path once the tendon pulls, at the
    // pennation of a fiber found from h = (path length / optimal) - tendon_slack_length (its
    // units mixed as OpenSim mixes them).
    if (std::abs(tendon) > kRoundoff) {
      const double h = path_norm - m.tendon_slack_length, w = ofl * std::sin(phi0);
      const double fiber_new = std::sqrt(h * h + w * w) / ofl;
      velocity = path.lengthening_speed * p_.time_scale / ofl *
                 std::cos(PennationOf(fiber_new, 1.0, phi0));
    }
  } else {
    velocity = FiberVelocity(z[0], ActiveForceLength(lceN), std::max(tendon / ca - passive, 0.0));
  }
  out.fiber_velocity = velocity * ofl / p_.time_scale;
  out.tendon_force = tendon * m.max_isometric_force;
  out.passive_fiber_force = passive * m.max_isometric_force;
  // OpenSim's getActiveFiberForce for the deprecated muscles: the fiber force the tendon
  // implies, less the passive force.
  out.active_fiber_force = out.tendon_force / ca - out.passive_fiber_force;
  return out;
}

void Schutte1993Muscle::CalcStateVariableDerivatives(Eigen::Ref<const VecX> z, double excitation,
                                                     const PathKinematics& /*path*/,
                                                     const MuscleQuantities& quantities,
                                                     Eigen::Ref<VecX> zdot) const {
  zdot[0] = ActivationRate(z[0], excitation);
  zdot[1] = quantities.fiber_velocity;
}

DeprecatedMuscleCurves Schutte1993Muscle::Curves() const {
  return {
      .tendon_force = [this](double strain) { return TendonForce(strain); },
      .tendon_force_in_stiffness =
          [this](double strain) { return p_.tendon_force_length_curve->Calc(strain); },
      .active_force_length =
          [this](double lceN) { return p_.active_force_length_curve->Calc(lceN); },
      .passive_force_length = [this](double lceN) { return PassiveForce(lceN); },
      .pennation = [this](double fiber_length) { return Pennation(fiber_length); },
  };
}

double Schutte1993Muscle::IsometricImbalance(double activation, double fiber_length,
                                             double path_length) const {
  return DeprecatedIsometricImbalance(p_.muscle, Curves(), activation, fiber_length, path_length);
}

EquilibriumStatus Schutte1993Muscle::Equilibrate(const PathKinematics& path,
                                                 const std::string& component,
                                                 Eigen::Ref<VecX> z) const {
  const DeprecatedEquilibrium e =
      SolveDeprecatedIsometricFiberLength(p_.muscle, Curves(), z[0], path.length, component);
  z[1] = e.fiber_length;
  return e.status;
}

}  // namespace sinew::muscles

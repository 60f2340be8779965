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
// computeIsometricForce's iteration: at most 100 steps, done when the forces agree to 0.01 N.
constexpr int kMaxIterations = 100;
constexpr double kForceErrorLimit = 0.01;  // N
// Its estimate of a tendon's minimum stiffness: elastic modulus 1200 over maximum stress 32.
constexpr double kTendonModulusOverMaxStress = 1200.0 / 32.0;

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

namespace {

// OpenSim's guess of the fiber and tendon at one fiber length: the tendon never shorter than
// its slack length (the fiber then takes the rest of the path at the pennation of that length).
struct IsometricGuess {
  double fiber;   // m
  double cosine;  // of the pennation angle
  double tendon;  // m
};

IsometricGuess GuessAt(const Schutte1993Muscle& muscle, double fiber, double path_length) {
  const MuscleParameters& m = muscle.parameters().muscle;
  IsometricGuess g{fiber, std::cos(muscle.Pennation(fiber)), 0.0};
  g.tendon = path_length - g.fiber * g.cosine;
  if (g.tendon < m.tendon_slack_length) {
    const double width = m.optimal_fiber_length * std::sin(m.pennation_angle_at_optimal);
    g.tendon = m.tendon_slack_length;
    g.cosine = std::cos(std::atan(width / (path_length - g.tendon)));
    g.fiber = (path_length - g.tendon) / g.cosine;
  }
  return g;
}

}  // namespace

double Schutte1993Muscle::IsometricImbalance(double activation, double fiber_length,
                                             double path_length) const {
  const MuscleParameters& m = p_.muscle;
  const double lceN = fiber_length / m.optimal_fiber_length;
  const double ca = std::cos(Pennation(fiber_length));
  const double strain = (path_length - fiber_length * ca) / m.tendon_slack_length - 1.0;
  const double active = std::max(p_.active_force_length_curve->Calc(lceN) * activation, 0.0);
  return m.max_isometric_force *
         (TendonForce(strain) - (active + std::max(PassiveForce(lceN), 0.0)) * ca);
}

EquilibriumStatus Schutte1993Muscle::Equilibrate(const PathKinematics& path,
                                                 const std::string& component,
                                                 Eigen::Ref<VecX> z) const {
  const MuscleParameters& m = p_.muscle;
  const double a = z[0], length = path.length, ofl = m.optimal_fiber_length;
  const double fmax = m.max_isometric_force, slack = m.tendon_slack_length;
  const double width = ofl * std::sin(m.pennation_angle_at_optimal);
  if (!std::isfinite(a) || !std::isfinite(length)) {
    throw Error(SourceLocation{}, component,
                "cannot equilibrate: activation or path length is not finite");
  }
  // A path shorter than the tendon's slack length: no force; the fibers as long as the muscle
  // is wide (OpenSim's answer).
  if (length < slack) {
    z[1] = width;
    return EquilibriumStatus::kBalanced;
  }
  auto active = [&](double fiber) { return p_.active_force_length_curve->Calc(fiber / ofl); };

  // OpenSim's computeIsometricForce: from the optimal fiber length, steps of
  // error / (fiber stiffness / cos + tendon stiffness) (at most half an optimal length), and a
  // secant step whenever the error changes sign, until the forces agree to 0.01 N.
  IsometricGuess g = GuessAt(*this, ofl, length);
  g.fiber = std::max(g.fiber, width);
  double error = 0.0, old_fiber = g.fiber;
  for (int i = 0; i < kMaxIterations; ++i) {
    const double act = std::max(active(g.fiber) * a, 0.0);
    const double pas = std::max(PassiveForce(g.fiber / ofl), 0.0);
    const double strain = g.tendon / slack - 1.0;
    const double old_error = i == 0 ? fmax * (TendonForce(strain) - (act + pas) * g.cosine) : error;
    error = fmax * (TendonForce(strain) - (act + pas) * g.cosine);
    if (std::abs(error) <= kForceErrorLimit) break;
    if ((error >= 0.0) != (old_error >= 0.0)) {
      const double percent = std::abs(error) / (std::abs(error) + std::abs(old_error));
      const double before = old_fiber;
      old_fiber = g.fiber;
      g.fiber += percent * (before - g.fiber);
    } else {
      const double tendon_stiffness =
          std::max(p_.tendon_force_length_curve->Calc(strain) * fmax / slack,
                   (act + pas) * kTendonModulusOverMaxStress * fmax / slack);
      const double fiber_stiffness = fmax / ofl * (active(g.fiber) + PassiveForce(g.fiber / ofl));
      const double change =
          std::min(std::abs(error / (fiber_stiffness / g.cosine + tendon_stiffness)), 0.5 * ofl);
      old_fiber = g.fiber;
      g.fiber += error > 0.0 ? change : -change;
    }
    g = GuessAt(*this, g.fiber, length);
  }

  if (!(std::abs(error) <= kForceErrorLimit)) {
    throw Error(SourceLocation{}, component,
                "no muscle-tendon equilibrium at path length " + std::to_string(length) +
                    " m and activation " + std::to_string(a) + ": after " +
                    std::to_string(kMaxIterations) +
                    " iterations tendon and fiber forces differ by " +
                    std::to_string(std::abs(error)) + " N (OpenSim stops at 0.01 N)");
  }
  z[1] = g.fiber;
  return EquilibriumStatus::kBalanced;
}

}  // namespace sinew::muscles

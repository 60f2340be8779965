#include <sinew/common/error.h>
#include <sinew/muscles/thelen2003_muscle_deprecated.h>

#include <cmath>
#include <numbers>

namespace sinew::muscles {
namespace {

// OpenSim 2.x's test for "equal" (SimmMacros' ROUNDOFF_ERROR).
constexpr double kRoundoff = 2e-13;

// Pennation of a fiber of length lce with muscle width w: asin(w / lce), pi/2 when the fiber
// is no longer than the width, 0 for a zero-length fiber.
double Pennation(double lce, double width) {
  if (lce < 2.220446049250313e-16) return 0.0;
  const double s = width / lce;
  if (!(s > 0.0)) return 0.0;
  return s >= 1.0 ? std::numbers::pi / 2 : std::asin(s);
}

}  // namespace

Thelen2003MuscleDeprecated::Thelen2003MuscleDeprecated(
    const Thelen2003DeprecatedParameters& parameters)
    : p_(parameters) {
  auto require = [](bool ok, const char* what) {
    if (!ok) throw Error(SourceLocation{}, "", what);
  };
  require(p_.muscle.optimal_fiber_length > 0.0, "optimal_fiber_length must be greater than zero");
  require(p_.muscle.tendon_slack_length > 0.0, "tendon_slack_length must be greater than zero");
  require(p_.activation_time_constant > 0.0 && p_.deactivation_time_constant > 0.0,
          "activation and deactivation time constants must be greater than zero");
  require(p_.FmaxTendonStrain > 0.0 && p_.FmaxMuscleStrain > 0.0 && p_.KshapeActive > 0.0 &&
              p_.Af > 0.0 && p_.Flen > 1.0,
          "FmaxTendonStrain, FmaxMuscleStrain, KshapeActive and Af must be positive, Flen > 1");
}

std::vector<std::string> Thelen2003MuscleDeprecated::StateVariableNames() const {
  return {"activation", "fiber_length"};
}

void Thelen2003MuscleDeprecated::SetDefaultStateVariables(Eigen::Ref<VecX> z) const {
  z[0] = p_.default_activation;
  z[1] = p_.default_fiber_length;
}

double Thelen2003MuscleDeprecated::TendonForce(double strain) const {
  constexpr double kToeShape = 3.0, kToeForce = 0.333333;
  const double toe = 0.609 * p_.FmaxTendonStrain;
  const double slope = 1.712 / p_.FmaxTendonStrain;
  double force = 0.0;
  if (strain > toe) {
    force = slope * (strain - toe) + kToeForce;
  } else if (strain > 0.0) {
    force = kToeForce * (std::exp(kToeShape * strain / toe) - 1.0) / (std::exp(kToeShape) - 1.0);
  }
  return force + 0.001 * (1.0 + strain);
}

double Thelen2003MuscleDeprecated::PassiveForce(double lceN) const {
  const double k = p_.KshapePassive, e0 = p_.FmaxMuscleStrain;
  if (lceN > 1.0 + e0) {
    const double slope = k / e0 * std::exp(k) / std::exp(k);
    return 1.0 + slope * (lceN - (1.0 + e0));
  }
  return std::exp(k * (lceN - 1.0) / e0) / std::exp(k);
}

double Thelen2003MuscleDeprecated::FiberVelocity(double a, double fal, double force) const {
  constexpr double kEpsilon = 1e-6;
  a = std::max(a, kEpsilon);
  const double fa = a * fal, d = p_.damping, af = p_.Af, flen = p_.Flen;
  auto concentric = [&](double f) { return (f - fa) / (fa + f / af + d); };
  auto eccentric = [&](double f) {
    return (f - fa) / ((2.0 + 2.0 / af) * (fa * flen - f) / (flen - 1.0) + d);
  };
  if (force < fa) {
    if (force >= 0.0) return concentric(force);
    // Below zero force: the secant of the curve over [0, 1e-6] continued (OpenSim 2.x's rule).
    const double v0 = concentric(0.0), v1 = concentric(kEpsilon);
    return v0 + force * (v1 - v0) / kEpsilon;
  }
  const double f0 = 0.95 * fa * flen;
  if (force < f0) return eccentric(force);
  const double f1 = (0.95 + kEpsilon) * fa * flen;
  const double v0 = eccentric(f0), v1 = eccentric(f1);
  return v0 + (v1 - v0) / (f1 - f0) * (force - f0);
}

MuscleQuantities Thelen2003MuscleDeprecated::Calc(Eigen::Ref<const VecX> z, double /*excitation*/,
                                                  const PathKinematics& path) const {
  const MuscleParameters& m = p_.muscle;
  const double ofl = m.optimal_fiber_length;
  MuscleQuantities out;
  out.activation = z[0];
  const double a = z[0];
  out.fiber_length = z[1];
  const double lceN = z[1] / ofl;
  // Pennation of the normalized fiber with the normalized width sin(phi_opt).
  out.pennation_angle = Pennation(lceN, std::sin(m.pennation_angle_at_optimal));
  const double ca = std::cos(out.pennation_angle);
  const double tendon_norm = path.length / ofl - lceN * ca;
  out.tendon_length = tendon_norm * ofl;
  const double rest = m.tendon_slack_length / ofl;
  const double tendon = TendonForce((tendon_norm - rest) / rest);
  const double passive = PassiveForce(lceN);
  const double fal = ActiveForceLength(lceN);
  const double vmax = (a < 1.0 ? p_.Vmax0 + a * (p_.Vmax - p_.Vmax0) : p_.Vmax) * ofl;  // m/s
  double dlceN = 0.0;
  if (std::abs(ca) <= kRoundoff) {
    // Fibers at 90 degrees: OpenSim 2.x moves the fiber with the path.
    if (std::abs(tendon) > kRoundoff) {
      const double h = path.length / ofl - m.tendon_slack_length;
      const double w = ofl * std::sin(m.pennation_angle_at_optimal);
      const double lce_new = std::sqrt(h * h + w * w) / ofl;
      dlceN = path.lengthening_speed /
              (vmax * std::cos(Pennation(lce_new, std::sin(m.pennation_angle_at_optimal))));
    }
  } else {
    dlceN = FiberVelocity(a, fal, tendon / ca - passive);
  }
  out.fiber_velocity = dlceN * vmax;
  out.tendon_force = tendon * m.max_isometric_force;
  out.passive_fiber_force = passive * m.max_isometric_force;
  out.active_fiber_force = (tendon / ca - passive) * m.max_isometric_force;
  return out;
}

void Thelen2003MuscleDeprecated::CalcStateVariableDerivatives(Eigen::Ref<const VecX> z,
                                                              double excitation,
                                                              const PathKinematics& /*path*/,
                                                              const MuscleQuantities& quantities,
                                                              Eigen::Ref<VecX> zdot) const {
  const double a = z[0];
  zdot[0] = (excitation - a) /
            (excitation >= a ? p_.activation_time_constant : p_.deactivation_time_constant);
  zdot[1] = quantities.fiber_velocity;
}

double Thelen2003MuscleDeprecated::ActiveForceLength(double lceN) const {
  return std::exp(-(lceN - 1.0) * (lceN - 1.0) / p_.KshapeActive);
}

DeprecatedMuscleCurves Thelen2003MuscleDeprecated::Curves() const {
  return {
      .tendon_force = [this](double strain) { return TendonForce(strain); },
      .tendon_force_in_stiffness = [this](double strain) { return TendonForce(strain); },
      .active_force_length = [this](double lceN) { return ActiveForceLength(lceN); },
      .passive_force_length = [this](double lceN) { return PassiveForce(lceN); },
      .pennation =
          [this](double fiber_length) {
            return Pennation(fiber_length / p_.muscle.optimal_fiber_length,
                             std::sin(p_.muscle.pennation_angle_at_optimal));
          },
  };
}

double Thelen2003MuscleDeprecated::IsometricImbalance(double activation, double fiber_length,
                                                      double path_length) const {
  return DeprecatedIsometricImbalance(p_.muscle, Curves(), activation, fiber_length, path_length);
}

EquilibriumStatus Thelen2003MuscleDeprecated::Equilibrate(const PathKinematics& path,
                                                          const std::string& component,
                                                          Eigen::Ref<VecX> z) const {
  const DeprecatedEquilibrium e =
      SolveDeprecatedIsometricFiberLength(p_.muscle, Curves(), z[0], path.length, component);
  z[1] = e.fiber_length;
  return e.status;
}

}  // namespace sinew::muscles

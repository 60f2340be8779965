#include <sinew/common/error.h>
#include <sinew/muscles/deprecated_muscle_equilibrium.h>

#include <algorithm>
#include <cmath>

namespace sinew::muscles {
namespace {

// At most 100 steps, done when the forces agree to 0.01 N.
constexpr int kMaxIterations = 100;
constexpr double kForceErrorLimit = 0.01;  // N
// The estimate of a tendon's minimum stiffness: elastic modulus 1200 over maximum stress 32.
constexpr double kTendonModulusOverMaxStress = 1200.0 / 32.0;

// The fiber and tendon at one fiber length: the tendon never shorter than its slack length
// (the fiber then takes the rest of the path at the pennation of a muscle of constant width).
struct Guess {
  double fiber;   // m
  double cosine;  // of the pennation angle
  double tendon;  // m
};

Guess GuessAt(const MuscleParameters& m, const DeprecatedMuscleCurves& curves, double fiber,
              double path_length) {
  Guess g{fiber, std::cos(curves.pennation(fiber)), 0.0};
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

double DeprecatedIsometricImbalance(const MuscleParameters& m, const DeprecatedMuscleCurves& curves,
                                    double activation, double fiber_length, double path_length) {
  const double lceN = fiber_length / m.optimal_fiber_length;
  const double ca = std::cos(curves.pennation(fiber_length));
  const double strain = (path_length - fiber_length * ca) / m.tendon_slack_length - 1.0;
  const double active = std::max(curves.active_force_length(lceN) * activation, 0.0);
  const double passive = std::max(curves.passive_force_length(lceN), 0.0);
  return m.max_isometric_force * (curves.tendon_force(strain) - (active + passive) * ca);
}

DeprecatedEquilibrium SolveDeprecatedIsometricFiberLength(const MuscleParameters& m,
                                                          const DeprecatedMuscleCurves& curves,
                                                          double activation, double path_length,
                                                          const std::string& component) {
  const double a = activation, length = path_length, ofl = m.optimal_fiber_length;
  const double fmax = m.max_isometric_force, slack = m.tendon_slack_length;
  const double width = ofl * std::sin(m.pennation_angle_at_optimal);
  if (!std::isfinite(a) || !std::isfinite(length)) {
    throw Error(SourceLocation{}, component,
                "cannot equilibrate: activation or path length is not finite");
  }
  if (length < slack) return {width, EquilibriumStatus::kBalanced};

  Guess g = GuessAt(m, curves, ofl, length);
  g.fiber = std::max(g.fiber, width);
  double error = 0.0, old_fiber = g.fiber;
  for (int i = 0; i < kMaxIterations; ++i) {
    const double act = std::max(curves.active_force_length(g.fiber / ofl) * a, 0.0);
    const double pas = std::max(curves.passive_force_length(g.fiber / ofl), 0.0);
    const double strain = g.tendon / slack - 1.0;
    const double old_error = error;
    error = fmax * (curves.tendon_force(strain) - (act + pas) * g.cosine);
    if (std::abs(error) <= kForceErrorLimit) break;
    if (i > 0 && (error >= 0.0) != (old_error >= 0.0)) {
      const double percent = std::abs(error) / (std::abs(error) + std::abs(old_error));
      const double before = old_fiber;
      old_fiber = g.fiber;
      g.fiber += percent * (before - g.fiber);
    } else {
      const double tendon_stiffness =
          std::max(curves.tendon_force_in_stiffness(strain) * fmax / slack,
                   (act + pas) * kTendonModulusOverMaxStress * fmax / slack);
      const double fiber_stiffness =
          fmax / ofl *
          (curves.active_force_length(g.fiber / ofl) + curves.passive_force_length(g.fiber / ofl));
      const double change =
          std::min(std::abs(error / (fiber_stiffness / g.cosine + tendon_stiffness)), 0.5 * ofl);
      old_fiber = g.fiber;
      g.fiber += error > 0.0 ? change : -change;
    }
    g = GuessAt(m, curves, g.fiber, length);
  }
  if (std::abs(error) <= kForceErrorLimit) return {g.fiber, EquilibriumStatus::kBalanced};
  if (g.tendon == slack) return {g.fiber, EquilibriumStatus::kTendonAtSlackLength};
  throw Error(SourceLocation{}, component,
              "no muscle-tendon equilibrium at path length " + std::to_string(length) +
                  " m and activation " + std::to_string(a) + ": after " +
                  std::to_string(kMaxIterations) +
                  " iterations tendon and fiber forces differ by " +
                  std::to_string(std::abs(error)) + " N (OpenSim stops at 0.01 N)");
}

}  // namespace sinew::muscles

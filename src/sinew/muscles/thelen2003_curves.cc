#include <sinew/common/error.h>
#include <sinew/muscles/thelen2003_curves.h>

#include <algorithm>
#include <cmath>

namespace sinew::muscles {
namespace {

// The tendon's toe region: its strain e_toe and the slope of the linear region, from
// F_toe = 0.33 at e_toe, k_toe = 3, the force 1 at FmaxTendonStrain e0 and a continuous slope:
// slope = 3 F_toe / (e_toe (1 - exp(-3))) = (1 - F_toe) / (e0 - e_toe).
constexpr double kToeShape = 3.0;
constexpr double kToeForce = 0.33;

double ToeStrain(double e0) {
  const double e3 = std::exp(kToeShape);
  return 99.0 * e0 * e3 / (166.0 * e3 - 67.0);
}

double LinearSlope(double e0) { return (1.0 - kToeForce) / (e0 - ToeStrain(e0)); }

// Thelen's force-velocity relation solved for the velocity, in the form b (v / vmax') =
// (F - a fal) with vmax' = 0.25 + 0.75 a: b and db/dF on the concentric and eccentric sides.
struct VelocityDenominator {
  double b, db;
};

VelocityDenominator Denominator(const Thelen2003CurveParameters& p, double afl, double force) {
  if (force <= afl) return {afl + force / p.Af, 1.0 / p.Af};
  const double k = (2.0 + 2.0 / p.Af) / (p.Flen - 1.0);
  return {k * (afl * p.Flen - force), -k};
}

// The point where the curve turns into its linear extrapolation, or force itself inside.
double CurveForce(const Thelen2003CurveParameters& p, double afl, double force, bool* inside) {
  const double eccentric_end = p.fv_linear_extrap_threshold * afl * p.Flen;
  *inside = force > 0.0 && force < eccentric_end;
  if (*inside) return force;
  return force <= 0.0 ? 0.0 : eccentric_end;
}

}  // namespace

double ThelenActiveForceLength(const Thelen2003CurveParameters& p, double lceN) {
  const double x = lceN - 1.0;
  return std::exp(-x * x / p.KshapeActive);
}

double ThelenActiveForceLengthSlope(const Thelen2003CurveParameters& p, double lceN) {
  const double x = lceN - 1.0;
  return -2.0 * x / p.KshapeActive * std::exp(-x * x / p.KshapeActive);
}

double ThelenPassiveForceLength(const Thelen2003CurveParameters& p, double lceN) {
  if (lceN <= 1.0) return 0.0;
  return (std::exp(p.KshapePassive * (lceN - 1.0) / p.FmaxMuscleStrain) - 1.0) /
         (std::exp(p.KshapePassive) - 1.0);
}

double ThelenPassiveForceLengthSlope(const Thelen2003CurveParameters& p, double lceN) {
  if (lceN <= 1.0) return 0.0;
  return p.KshapePassive / p.FmaxMuscleStrain *
         std::exp(p.KshapePassive * (lceN - 1.0) / p.FmaxMuscleStrain) /
         (std::exp(p.KshapePassive) - 1.0);
}

double ThelenTendonForceLength(const Thelen2003CurveParameters& p, double tlN) {
  const double strain = tlN - 1.0;
  const double toe = ToeStrain(p.FmaxTendonStrain);
  if (strain > toe) return LinearSlope(p.FmaxTendonStrain) * (strain - toe) + kToeForce;
  if (strain > 0.0) {
    return kToeForce / (std::exp(kToeShape) - 1.0) * (std::exp(kToeShape * strain / toe) - 1.0);
  }
  return 0.0;
}

double ThelenTendonForceLengthSlope(const Thelen2003CurveParameters& p, double tlN) {
  const double strain = tlN - 1.0;
  const double toe = ToeStrain(p.FmaxTendonStrain);
  if (strain > toe) return LinearSlope(p.FmaxTendonStrain);
  if (strain > 0.0) {
    return kToeForce / (std::exp(kToeShape) - 1.0) * kToeShape / toe *
           std::exp(kToeShape * strain / toe);
  }
  return 0.0;
}

double ThelenFiberVelocity(const Thelen2003CurveParameters& p, double a, double fal, double force) {
  const double afl = a * fal;
  const double scale = 0.25 + 0.75 * a;
  bool inside = false;
  const double f0 = CurveForce(p, afl, force, &inside);
  const VelocityDenominator d = Denominator(p, afl, f0);
  const double v0 = scale * (f0 - afl) / d.b;
  if (inside) return v0;
  return v0 + ThelenFiberVelocitySlope(p, a, fal, force) * (force - f0);
}

double ThelenFiberVelocitySlope(const Thelen2003CurveParameters& p, double a, double fal,
                                double force) {
  const double afl = a * fal;
  const double scale = 0.25 + 0.75 * a;
  bool inside = false;
  const double f0 = CurveForce(p, afl, force, &inside);
  const VelocityDenominator d = Denominator(p, afl, f0);
  return scale / d.b - scale * (f0 - afl) / (d.b * d.b) * d.db;
}

double ThelenForceVelocity(const Thelen2003CurveParameters& p, double a, double fal, double dlceN) {
  // Newton on the force F = a fal fv, from the isometric force; the relation is monotonic
  // and piecewise smooth with linear ends, so this converges in a few steps.
  double force = a * fal;
  constexpr int kMaxIterations = 100;
  for (int i = 0; i < kMaxIterations; ++i) {
    const double error = ThelenFiberVelocity(p, a, fal, force) - dlceN;
    if (std::abs(error) < 1e-14 * (1.0 + std::abs(dlceN))) break;
    const double slope = ThelenFiberVelocitySlope(p, a, fal, force);
    if (!(std::abs(slope) > 1e-300)) break;
    force -= error / slope;
  }
  return std::max(0.0, force / (a * fal));
}

}  // namespace sinew::muscles

// Millard2012's curves against the properties that define them: the points and slopes each
// passes through, monotonicity, derivatives against central differences, the integral against
// Simpson's rule, the inverse force-velocity curve against the curve, and one corner evaluated
// independently (power-basis Bernstein polynomials and bisection instead of de Casteljau and
// Newton).
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/muscles/millard2012_curves.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

namespace sinew::muscles {
namespace {

// Value and slope at x within `tolerance` of the given ones.
void ExpectPointAndSlope(const SmoothSegmentedCurve& c, double x, double y, double dydx,
                         double tolerance = 1e-12) {
  EXPECT_NEAR(c.Value(x), y, tolerance * std::max(1.0, std::abs(y))) << "at x = " << x;
  EXPECT_NEAR(c.Derivative(x, 1), dydx, tolerance * std::max(1.0, std::abs(dydx)))
      << "slope at x = " << x;
}

// Samples of [a, b] (n + 1 points).
std::vector<double> Samples(double a, double b, int n) {
  std::vector<double> x;
  for (int i = 0; i <= n; ++i) x.push_back(a + (b - a) * i / n);
  return x;
}

// Central difference of g at x, Richardson-extrapolated from steps h and h/2 (truncation
// O(h^4)); `bound` gets the estimate of the plain difference's truncation error, |D(h) -
// D(h/2)|, which is large where a corner turns sharply (the tendon's toe: third derivatives
// near 1e7).
double Derivative(const std::function<double(double)>& g, double x, double h, double* bound) {
  const double coarse = (g(x + h) - g(x - h)) / (2 * h);
  const double fine = (g(x + h / 2) - g(x - h / 2)) / h;
  *bound = std::abs(coarse - fine);
  return (4 * fine - coarse) / 3;
}

// First and second derivatives against extrapolated central differences (step 1e-5: rounding
// eps |f| / h about 1e-10), over the Bezier part and the lines beyond it. The tolerance is
// 1e-7 relative plus a tenth of the plain difference's estimated truncation error, which bounds
// the extrapolated one's. The curve is C2 but not C3 where segments join (and where it meets its
// lines), so differences straddling a joint are left out and the joints are checked for
// continuity of value, slope and curvature instead.
void ExpectDerivativesMatchFiniteDifferences(const SmoothSegmentedCurve& c) {
  const double h = 1e-5;
  const double width = c.x1() - c.x0();
  std::vector<double> joints = {c.x1()};
  for (const QuinticBezierSegment& s : c.segments()) joints.push_back(s.x[0]);
  // Continuity: the jump across a joint, evaluated at +-e, shrinks in proportion to e (it is
  // the next derivative times 2e), down to rounding.
  for (double joint : joints) {
    for (int order = 0; order <= 2; ++order) {
      auto jump = [&](double e) {
        return std::abs(c.Derivative(joint + e, order) - c.Derivative(joint - e, order));
      };
      const double scale = std::max(1.0, std::abs(c.Derivative(joint, order)));
      EXPECT_LE(jump(1e-10), 0.02 * jump(1e-8) + 1e-7 * scale)
          << "order " << order << " at joint " << joint;
    }
  }
  auto near_joint = [&](double x) {
    for (double joint : joints) {
      if (std::abs(x - joint) < 2 * h) return true;
    }
    return false;
  };
  auto value = [&](double x) { return c.Value(x); };
  auto slope_of = [&](double x) { return c.Derivative(x, 1); };
  for (double x : Samples(c.x0() - 0.1 * width, c.x1() + 0.1 * width, 997)) {
    if (near_joint(x)) continue;
    double bound1 = 0, bound2 = 0;
    const double d1 = Derivative(value, x, h, &bound1);
    const double d2 = Derivative(slope_of, x, h, &bound2);
    const double slope = c.Derivative(x, 1), curvature = c.Derivative(x, 2);
    EXPECT_NEAR(slope, d1, 1e-7 * std::max(1.0, std::abs(slope)) + 0.1 * bound1) << "x = " << x;
    EXPECT_NEAR(curvature, d2, 1e-7 * std::max(1.0, std::abs(curvature)) + 0.1 * bound2)
        << "x = " << x;
    const SmoothSegmentedCurve::ValueAndSlope both = c.ValueAndDerivative(x);
    EXPECT_EQ(both.value, c.Value(x));
    EXPECT_EQ(both.slope, slope);
  }
}

// y never decreases (sign +1) or never increases (-1) over [a, b].
void ExpectMonotonic(const SmoothSegmentedCurve& c, double a, double b, int sign) {
  double previous = c.Value(a);
  for (double x : Samples(a, b, 2000)) {
    const double y = c.Value(x);
    EXPECT_GE(sign * (y - previous), -1e-15) << "x = " << x;
    EXPECT_GE(sign * c.Derivative(x, 1), -1e-12) << "x = " << x;
    previous = y;
  }
}

TEST(Millard2012CurvesTest, ActiveForceLengthPeaksAtOneAndVanishesAtItsLimits) {
  const ActiveForceLengthCurveParameters p;  // OpenSim's defaults
  const SmoothSegmentedCurve c = MakeActiveForceLengthCurve(p);
  ExpectPointAndSlope(c, 1.0, 1.0, 0.0);
  ExpectPointAndSlope(c, p.min_norm_active_fiber_length, p.minimum_value, 0.0);
  ExpectPointAndSlope(c, p.max_norm_active_fiber_length, p.minimum_value, 0.0);
  ExpectPointAndSlope(c, 0.0, p.minimum_value, 0.0);  // constant beyond the limits
  ExpectPointAndSlope(c, 2.5, p.minimum_value, 0.0);
  // The shallow ascending limb ends half a sarcomere width (0.05) before the plateau, where
  // the curve has the shallow slope.
  const double xs = 0.95, x1 = p.transition_norm_fiber_length;
  ExpectPointAndSlope(c, x1 + 0.5 * (xs - x1), 1.0 - 0.5 * p.shallow_ascending_slope * (xs - x1),
                      p.shallow_ascending_slope);
  ExpectMonotonic(c, p.min_norm_active_fiber_length, 1.0, +1);
  ExpectMonotonic(c, 1.0, p.max_norm_active_fiber_length, -1);
  ExpectDerivativesMatchFiniteDifferences(c);
}

TEST(Millard2012CurvesTest, ForceVelocityPassesThroughItsThreeDefiningPoints) {
  const ForceVelocityCurveParameters p;
  const SmoothSegmentedCurve c = MakeForceVelocityCurve(p);
  ExpectPointAndSlope(c, -1.0, 0.0, p.concentric_slope_at_vmax);
  ExpectPointAndSlope(c, 0.0, 1.0, p.isometric_slope);
  ExpectPointAndSlope(c, 1.0, p.max_eccentric_velocity_force_multiplier, p.eccentric_slope_at_vmax);
  // Near vmax (|v| = 0.9) the slopes are the "near" ones, on the line averaging the two slopes.
  ExpectPointAndSlope(c, -0.9, 0.05 * (p.concentric_slope_near_vmax + p.concentric_slope_at_vmax),
                      p.concentric_slope_near_vmax);
  ExpectPointAndSlope(c, 0.9,
                      1.4 - 0.05 * (p.eccentric_slope_near_vmax + p.eccentric_slope_at_vmax),
                      p.eccentric_slope_near_vmax);
  ExpectMonotonic(c, -1.2, 1.2, +1);
  ExpectDerivativesMatchFiniteDifferences(c);
}

TEST(Millard2012CurvesTest, ForceVelocityInverseInvertsTheCurveEverywhere) {
  const ForceVelocityCurveParameters p = DefaultForceVelocityInverseCurveParameters();
  EXPECT_EQ(p.concentric_slope_at_vmax, 0.1);
  EXPECT_EQ(p.eccentric_slope_at_vmax, 0.1);
  const SmoothSegmentedCurve fv = MakeForceVelocityCurve(p);
  const SmoothSegmentedCurve inverse = MakeForceVelocityInverseCurve(p);
  for (double v : Samples(-1.3, 1.3, 1001)) {
    EXPECT_NEAR(inverse.Value(fv.Value(v)), v, 1e-12) << "v = " << v;
    EXPECT_NEAR(inverse.Derivative(fv.Value(v), 1) * fv.Derivative(v, 1), 1.0, 1e-10);
  }
  ExpectMonotonic(inverse, -0.2, 1.6, +1);
  ExpectDerivativesMatchFiniteDifferences(inverse);
  // Zero slopes at vmax cannot be inverted.
  EXPECT_THROW(MakeForceVelocityInverseCurve(ForceVelocityCurveParameters{}), Error);
}

TEST(Millard2012CurvesTest, FiberForceLengthRisesFromItsZeroStrainToOneAtItsStrain) {
  const FiberForceLengthCurveParameters p;
  const SmoothSegmentedCurve c = MakeFiberForceLengthCurve(p);
  const double k_iso = 2.0 / 0.7;  // OpenSim's stiffness when the optional ones are absent
  ExpectPointAndSlope(c, 1.0, 0.0, 0.0);
  ExpectPointAndSlope(c, 1.7, 1.0, k_iso);
  ExpectPointAndSlope(c, 0.5, 0.0, 0.0);
  ExpectPointAndSlope(c, 2.0, 1.0 + k_iso * 0.3, k_iso);
  ExpectMonotonic(c, 0.8, 2.0, +1);
  ExpectDerivativesMatchFiniteDifferences(c);
  // Given explicitly (as Rajagopal2016 writes them), the optional properties are used.
  FiberForceLengthCurveParameters given = p;
  given.strain_at_zero_force = -0.1;
  given.stiffness_at_low_force = 0.2;
  given.stiffness_at_one_norm_force = 4.0;
  given.curviness = 0.75;
  const SmoothSegmentedCurve g = MakeFiberForceLengthCurve(given);
  ExpectPointAndSlope(g, 0.9, 0.0, 0.0);
  ExpectPointAndSlope(g, 1.7, 1.0, 4.0);
  given.curviness.reset();
  EXPECT_THROW(MakeFiberForceLengthCurve(given), Error);
}

TEST(Millard2012CurvesTest, TendonForceLengthIsOneAtItsStrainOnTheLinearPart) {
  const TendonForceLengthCurveParameters p;
  const SmoothSegmentedCurve c = MakeTendonForceLengthCurve(p);
  const double k_iso = 1.375 / 0.049;
  ExpectPointAndSlope(c, 1.0, 0.0, 0.0);
  ExpectPointAndSlope(c, 1.049, 1.0, k_iso);  // on the linear extension past the toe
  ExpectPointAndSlope(c, 0.9, 0.0, 0.0);
  // The toe ends at force 2/3 on the line of slope k_iso through (1.049, 1).
  const double x_toe = 1.049 + (2.0 / 3.0 - 1.0) / k_iso;
  EXPECT_NEAR(c.x1(), x_toe, 1e-15);
  ExpectPointAndSlope(c, x_toe, 2.0 / 3.0, k_iso);
  ExpectMonotonic(c, 0.95, 1.1, +1);
  ExpectDerivativesMatchFiniteDifferences(c);
  TendonForceLengthCurveParameters partial = p;
  partial.curviness = 0.5;
  EXPECT_THROW(MakeTendonForceLengthCurve(partial), Error);
}

TEST(Millard2012CurvesTest, CompressiveCurvesFallFromOneToZero) {
  const FiberCompressiveForceLengthCurveParameters pl;
  const SmoothSegmentedCurve length = MakeFiberCompressiveForceLengthCurve(pl);
  ExpectPointAndSlope(length, 0.0, 1.0, -2.0 / 0.5);
  ExpectPointAndSlope(length, 0.5, 0.0, 0.0);
  ExpectMonotonic(length, -0.1, 0.7, -1);
  ExpectDerivativesMatchFiniteDifferences(length);

  const FiberCompressiveForceCosPennationCurveParameters pc;
  const SmoothSegmentedCurve cosine = MakeFiberCompressiveForceCosPennationCurve(pc);
  const double cos_engaged = std::cos(85.0 * std::numbers::pi / 180.0);
  ExpectPointAndSlope(cosine, 0.0, 1.0, -2.0 / cos_engaged);
  ExpectPointAndSlope(cosine, cos_engaged, 0.0, 0.0);
  ExpectMonotonic(cosine, -0.05, 0.2, -1);
  ExpectDerivativesMatchFiniteDifferences(cosine);
}

// The one-corner curve evaluated independently: the control points from the corner's
// definition (tangents meeting at C, inner points at curviness 0.1 + 0.8 * 0.5 = 0.5 of the way
// to C), the quintic in power form, and u found by bisection.
TEST(Millard2012CurvesTest, OneCornerCurveAgreesWithAnIndependentEvaluation) {
  const SmoothSegmentedCurve c = MakeFiberCompressiveForceLengthCurve({});
  // Tangents: y = 1 - 4x from (0, 1) and y = 0 at (0.5, 0) meet at C = (0.25, 0).
  const double s = 0.5;
  const std::array<double, 6> px = {
      0.0, s * 0.25, s * 0.25, 0.5 + s * (0.25 - 0.5), 0.5 + s * (0.25 - 0.5), 0.5};
  const std::array<double, 6> py = {1.0, 1.0 + s * (0.0 - 1.0), 1.0 + s * (0.0 - 1.0), 0.0, 0.0,
                                    0.0};
  auto power_form = [](const std::array<double, 6>& p, double u) {
    const double w = 1.0 - u;
    return std::pow(w, 5) * p[0] + 5 * u * std::pow(w, 4) * p[1] +
           10 * u * u * std::pow(w, 3) * p[2] + 10 * std::pow(u, 3) * w * w * p[3] +
           5 * std::pow(u, 4) * w * p[4] + std::pow(u, 5) * p[5];
  };
  for (double x : Samples(0.0, 0.5, 50)) {
    double lo = 0.0, hi = 1.0;
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      (power_form(px, mid) < x ? lo : hi) = mid;
    }
    EXPECT_NEAR(c.Value(x), power_form(py, 0.5 * (lo + hi)), 1e-14) << "x = " << x;
  }
}

TEST(Millard2012CurvesTest, IntegralMatchesSimpsonsRuleAndItsDerivativeIsTheCurve) {
  const SmoothSegmentedCurve fpe = MakeFiberForceLengthCurve({});
  const SmoothSegmentedCurve fse = MakeTendonForceLengthCurve({});
  for (const SmoothSegmentedCurve* c : {&fpe, &fse}) {
    const double a = c->x0() - 0.05, b = c->x1() + 0.05;
    const int n = 20000;  // Simpson's error (b - a)^5 max|f''''| / (180 n^4), below 1e-12 here
    double simpson = c->Value(a) + c->Value(b);
    for (int i = 1; i < n; ++i) simpson += (i % 2 ? 4.0 : 2.0) * c->Value(a + (b - a) * i / n);
    simpson *= (b - a) / (3.0 * n);
    EXPECT_NEAR(c->Integral(b) - c->Integral(a), simpson, 1e-10);
    for (double x : Samples(a, b, 97)) {
      const double h = 1e-6;
      EXPECT_NEAR((c->Integral(x + h) - c->Integral(x - h)) / (2 * h), c->Value(x), 1e-7);
    }
    EXPECT_EQ(c->Integral(c->x0()), 0.0);
  }
}

TEST(Millard2012CurvesTest, ImpossiblePropertiesAreRefusedWithTheirNames) {
  ActiveForceLengthCurveParameters fal;
  fal.transition_norm_fiber_length = 1.2;
  try {
    MakeActiveForceLengthCurve(fal);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("ActiveForceLengthCurve"), std::string::npos);
  }
  ForceVelocityCurveParameters fv;
  fv.max_eccentric_velocity_force_multiplier = 0.9;
  EXPECT_THROW(MakeForceVelocityCurve(fv), Error);
  FiberCompressiveForceLengthCurveParameters compressive;
  compressive.stiffness_at_zero_length = -1.0;  // shallower than the corner allows
  compressive.curviness = 0.5;
  EXPECT_THROW(MakeFiberCompressiveForceLengthCurve(compressive), Error);
  EXPECT_THROW(MakeQuinticBezierCorner(0, 0, 1, 1, 1, 1, 1.5), Error);
  EXPECT_THROW(SmoothSegmentedCurve().Value(-1.0), Error);
}

}  // namespace
}  // namespace sinew::muscles

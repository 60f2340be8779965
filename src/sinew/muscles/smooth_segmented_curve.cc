#include <sinew/common/error.h>
#include <sinew/muscles/smooth_segmented_curve.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace sinew::muscles {

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// A Bezier polynomial of degree n <= 5 at u (de Casteljau's algorithm on its n + 1 points).
double EvalBezier(std::array<double, 6> p, int n, double u) {
  for (int level = n; level > 0; --level) {
    for (int i = 0; i < level; ++i) p[i] = (1.0 - u) * p[i] + u * p[i + 1];
  }
  return p[0];
}

// The value and the first two u-derivatives of a quintic Bezier coordinate at u.
struct BezierDerivatives {
  double value, d1, d2;
};
BezierDerivatives EvalQuintic(const std::array<double, 6>& p, double u) {
  std::array<double, 6> d1{}, d2{};
  for (int i = 0; i < 5; ++i) d1[i] = 5.0 * (p[i + 1] - p[i]);
  for (int i = 0; i < 4; ++i) d2[i] = 4.0 * (d1[i + 1] - d1[i]);
  return {EvalBezier(p, 5, u), EvalBezier(d1, 4, u), EvalBezier(d2, 3, u)};
}

}  // namespace

double ScaleCurviness(double curviness) { return 0.1 + 0.8 * curviness; }

QuinticBezierSegment MakeQuinticBezierCorner(double x0, double y0, double dydx0, double x1,
                                             double y1, double dydx1, double curviness) {
  if (!(curviness >= 0.0 && curviness <= 1.0)) {
    throw Error("quintic Bezier corner: curviness " + std::to_string(curviness) +
                " is outside [0, 1]");
  }
  // C, where the tangent lines at the two ends meet.
  const double xC = std::abs(dydx0 - dydx1) > std::sqrt(kEps)
                        ? (y1 - y0 - x1 * dydx1 + x0 * dydx0) / (dydx0 - dydx1)
                        : 0.5 * (x1 + x0);
  const double yC = (xC - x1) * dydx1 + y1;
  const double a = (xC - x0) * (xC - x0) + (yC - y0) * (yC - y0);
  const double b = (xC - x1) * (xC - x1) + (yC - y1) * (yC - y1);
  const double c = (x1 - x0) * (x1 - x0) + (y1 - y0) * (y1 - y0);
  if (!(c > a && c > b)) {
    throw Error("quintic Bezier corner from (" + std::to_string(x0) + ", " + std::to_string(y0) +
                ") to (" + std::to_string(x1) + ", " + std::to_string(y1) +
                "): the end slopes do not make a C-shaped corner");
  }
  const double x0_mid = x0 + curviness * (xC - x0);
  const double y0_mid = y0 + curviness * (yC - y0);
  const double x1_mid = x1 + curviness * (xC - x1);
  const double y1_mid = y1 + curviness * (yC - y1);
  return {{x0, x0_mid, x0_mid, x1_mid, x1_mid, x1}, {y0, y0_mid, y0_mid, y1_mid, y1_mid, y1}};
}

SmoothSegmentedCurve::SmoothSegmentedCurve(std::vector<QuinticBezierSegment> segments, double x0,
                                           double x1, double y0, double y1, double dydx0,
                                           double dydx1)
    : segments_(std::move(segments)),
      x0_(x0),
      x1_(x1),
      y0_(y0),
      y1_(y1),
      dydx0_(dydx0),
      dydx1_(dydx1) {
  if (segments_.empty()) throw Error("smooth segmented curve: no segments");
  for (size_t s = 0; s < segments_.size(); ++s) {
    const QuinticBezierSegment& seg = segments_[s];
    if (!(seg.x[5] > seg.x[0])) throw Error("smooth segmented curve: a segment does not advance in x");
    if (s > 0 && (seg.x[0] != segments_[s - 1].x[5] || seg.y[0] != segments_[s - 1].y[5])) {
      throw Error("smooth segmented curve: segment " + std::to_string(s) +
                  " does not start where the previous one ends");
    }
  }
}

SmoothSegmentedCurve::SegmentParameter SmoothSegmentedCurve::Locate(double x) const {
  int s = static_cast<int>(segments_.size()) - 1;
  for (int i = 0; i < static_cast<int>(segments_.size()); ++i) {
    if (x < segments_[i].x[5]) {
      s = i;
      break;
    }
  }
  const std::array<double, 6>& px = segments_[s].x;
  // Newton's method on x(u) = x, kept inside a bracket [lo, hi] that bisection shrinks whenever
  // a Newton step would leave it; x(u) increases with u.
  double lo = 0.0, hi = 1.0;
  double u = std::clamp((x - px[0]) / (px[5] - px[0]), 0.0, 1.0);
  const double tolerance = 4.0 * kEps * std::max({std::abs(px[0]), std::abs(px[5]), 1.0});
  for (int iteration = 0; iteration < 100; ++iteration) {
    const BezierDerivatives xu = EvalQuintic(px, u);
    const double f = xu.value - x;
    if (std::abs(f) <= tolerance) break;
    (f < 0.0 ? lo : hi) = u;
    double next = xu.d1 > 0.0 ? u - f / xu.d1 : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (next == u) break;
    u = next;
  }
  return {s, u};
}

double SmoothSegmentedCurve::Value(double x) const { return Derivative(x, 0); }

double SmoothSegmentedCurve::Derivative(double x, int order) const {
  if (order < 0 || order > 2) {
    throw Error("smooth segmented curve: derivative order " + std::to_string(order) +
                " (0, 1 or 2 are available)");
  }
  if (x < x0_) return order == 0 ? y0_ + dydx0_ * (x - x0_) : order == 1 ? dydx0_ : 0.0;
  if (x > x1_) return order == 0 ? y1_ + dydx1_ * (x - x1_) : order == 1 ? dydx1_ : 0.0;
  const SegmentParameter at = Locate(x);
  const QuinticBezierSegment& seg = segments_[at.segment];
  if (order == 0) return EvalBezier(seg.y, 5, at.u);
  const BezierDerivatives xu = EvalQuintic(seg.x, at.u);
  const BezierDerivatives yu = EvalQuintic(seg.y, at.u);
  if (order == 1) return yu.d1 / xu.d1;
  // d2y/dx2 = (y'' x' - y' x'') / x'^3, primes in u.
  return (yu.d2 * xu.d1 - yu.d1 * xu.d2) / (xu.d1 * xu.d1 * xu.d1);
}

SmoothSegmentedCurve::ValueAndSlope SmoothSegmentedCurve::ValueAndDerivative(double x) const {
  if (x < x0_) return {y0_ + dydx0_ * (x - x0_), dydx0_};
  if (x > x1_) return {y1_ + dydx1_ * (x - x1_), dydx1_};
  const SegmentParameter at = Locate(x);
  const QuinticBezierSegment& seg = segments_[at.segment];
  const BezierDerivatives xu = EvalQuintic(seg.x, at.u);
  const BezierDerivatives yu = EvalQuintic(seg.y, at.u);
  return {yu.value, yu.d1 / xu.d1};
}

double SmoothSegmentedCurve::SegmentIntegral(int s, double u) const {
  // y(v) x'(v) is a polynomial of degree 9 in v: 5-point Gauss-Legendre on [0, u] is exact.
  static constexpr std::array<double, 5> kNodes = {0.0, -0.5384693101056831, 0.5384693101056831,
                                                   -0.9061798459386640, 0.9061798459386640};
  static constexpr std::array<double, 5> kWeights = {0.5688888888888889, 0.4786286704993665,
                                                     0.4786286704993665, 0.2369268850561891,
                                                     0.2369268850561891};
  const QuinticBezierSegment& seg = segments_[s];
  double sum = 0.0;
  for (int k = 0; k < 5; ++k) {
    const double v = 0.5 * u * (kNodes[k] + 1.0);
    sum += kWeights[k] * EvalBezier(seg.y, 5, v) * EvalQuintic(seg.x, v).d1;
  }
  return 0.5 * u * sum;
}

double SmoothSegmentedCurve::Integral(double x) const {
  if (x <= x0_) return (x - x0_) * (y0_ + 0.5 * dydx0_ * (x - x0_));
  const double x_in = std::min(x, x1_);
  const SegmentParameter at = Locate(x_in);
  double integral = SegmentIntegral(at.segment, at.u);
  for (int s = 0; s < at.segment; ++s) integral += SegmentIntegral(s, 1.0);
  if (x > x1_) integral += (x - x1_) * (y1_ + 0.5 * dydx1_ * (x - x1_));
  return integral;
}

}  // namespace sinew::muscles

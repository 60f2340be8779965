#include <sinew/common/error.h>
#include <sinew/muscles/smooth_segmented_curve.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace sinew::muscles {

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// The monomial coefficients of a quintic Bezier coordinate: a_k = C(5, k) sum_i (-1)^(k-i)
// C(k, i) p_i.
std::array<double, 6> MonomialCoefficients(const std::array<double, 6>& p) {
  static constexpr int kBinomial[6][6] = {{1},          {1, 1},          {1, 2, 1},
                                          {1, 3, 3, 1}, {1, 4, 6, 4, 1}, {1, 5, 10, 10, 5, 1}};
  std::array<double, 6> a{};
  for (int k = 0; k <= 5; ++k) {
    double sum = 0.0;
    for (int i = 0; i <= k; ++i) sum += ((k - i) % 2 ? -1.0 : 1.0) * kBinomial[k][i] * p[i];
    a[k] = kBinomial[5][k] * sum;
  }
  return a;
}

// A quintic in monomial form at u, and its first two u-derivatives (Horner's rule).
double PolynomialValue(const std::array<double, 6>& a, double u) {
  return a[0] + u * (a[1] + u * (a[2] + u * (a[3] + u * (a[4] + u * a[5]))));
}
double PolynomialSlope(const std::array<double, 6>& a, double u) {
  return a[1] + u * (2 * a[2] + u * (3 * a[3] + u * (4 * a[4] + u * 5 * a[5])));
}
struct PolynomialDerivatives {
  double value, d1, d2;
};
PolynomialDerivatives EvalPolynomial(const std::array<double, 6>& a, double u) {
  return {PolynomialValue(a, u), PolynomialSlope(a, u),
          2 * a[2] + u * (6 * a[3] + u * (12 * a[4] + u * 20 * a[5]))};
}

// The u in [0, 1] at which x(u) = x: Newton's method from `u`, kept inside a bracket [lo, hi]
// that bisection shrinks whenever a Newton step would leave it (x(u) increases with u). Stops
// at a residual of a few ulps of x.
double SolveParameter(const std::array<double, 6>& ax, double x, double u, double tolerance) {
  double lo = 0.0, hi = 1.0;
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double value = PolynomialValue(ax, u);
    const double f = value - x;
    if (std::abs(f) <= tolerance) break;
    (f < 0.0 ? lo : hi) = u;
    const double slope = PolynomialSlope(ax, u);
    double next = slope > 0.0 ? u - f / slope : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (next == u) break;
    u = next;
  }
  return u;
}

// The tolerance on x for a segment: a few ulps of its largest coordinate.
double ParameterTolerance(const QuinticBezierSegment& seg) {
  return 4.0 * kEps * std::max({std::abs(seg.x[0]), std::abs(seg.x[5]), 1.0});
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
    if (!(seg.x[5] > seg.x[0]))
      throw Error("smooth segmented curve: a segment does not advance in x");
    if (s > 0 && (seg.x[0] != segments_[s - 1].x[5] || seg.y[0] != segments_[s - 1].y[5])) {
      throw Error("smooth segmented curve: segment " + std::to_string(s) +
                  " does not start where the previous one ends");
    }
    Polynomials poly;
    poly.x = MonomialCoefficients(seg.x);
    poly.y = MonomialCoefficients(seg.y);
    for (int j = 0; j < kGuessPoints; ++j) {
      const double t = static_cast<double>(j) / (kGuessPoints - 1);
      poly.u_at_x[j] =
          SolveParameter(poly.x, seg.x[0] + t * (seg.x[5] - seg.x[0]), t, ParameterTolerance(seg));
      const double slope = PolynomialSlope(poly.x, poly.u_at_x[j]);
      poly.du_dx[j] = slope > 0.0 && std::isfinite(1.0 / slope) ? 1.0 / slope : 0.0;
    }
    polynomials_.push_back(poly);
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
  const QuinticBezierSegment& seg = segments_[s];
  const Polynomials& poly = polynomials_[s];
  // First guess: the tabulated u, interpolated in x by the cubic Hermite polynomial through
  // the two neighbouring entries and their slopes du/dx (linearly where a slope is missing),
  // kept between the two entries (u(x) increases).
  const double t =
      std::clamp((x - seg.x[0]) / (seg.x[5] - seg.x[0]), 0.0, 1.0) * (kGuessPoints - 1);
  const int j = std::min(static_cast<int>(t), kGuessPoints - 2);
  const double w = t - j, u0 = poly.u_at_x[j], u1 = poly.u_at_x[j + 1];
  double guess = u0 + w * (u1 - u0);
  if (poly.du_dx[j] > 0.0 && poly.du_dx[j + 1] > 0.0) {
    const double hx = (seg.x[5] - seg.x[0]) / (kGuessPoints - 1);
    const double w2 = w * w, w3 = w2 * w;
    guess = (2 * w3 - 3 * w2 + 1) * u0 + (w3 - 2 * w2 + w) * hx * poly.du_dx[j] +
            (3 * w2 - 2 * w3) * u1 + (w3 - w2) * hx * poly.du_dx[j + 1];
    guess = std::clamp(guess, u0, u1);
  }
  return {s, SolveParameter(poly.x, x, guess, ParameterTolerance(seg))};
}

double SmoothSegmentedCurve::Value(double x) const { return Derivative(x, 0); }

void SmoothSegmentedCurve::CheckBuilt() const {
  if (segments_.empty()) throw Error("smooth segmented curve: evaluated before it was built");
}

double SmoothSegmentedCurve::Derivative(double x, int order) const {
  CheckBuilt();
  if (order < 0 || order > 2) {
    throw Error("smooth segmented curve: derivative order " + std::to_string(order) +
                " (0, 1 or 2 are available)");
  }
  if (x < x0_) return order == 0 ? y0_ + dydx0_ * (x - x0_) : order == 1 ? dydx0_ : 0.0;
  if (x > x1_) return order == 0 ? y1_ + dydx1_ * (x - x1_) : order == 1 ? dydx1_ : 0.0;
  const SegmentParameter at = Locate(x);
  const Polynomials& poly = polynomials_[at.segment];
  if (order == 0) return PolynomialValue(poly.y, at.u);
  const PolynomialDerivatives xu = EvalPolynomial(poly.x, at.u);
  const PolynomialDerivatives yu = EvalPolynomial(poly.y, at.u);
  if (order == 1) return yu.d1 / xu.d1;
  // d2y/dx2 = (y'' x' - y' x'') / x'^3, primes in u.
  return (yu.d2 * xu.d1 - yu.d1 * xu.d2) / (xu.d1 * xu.d1 * xu.d1);
}

SmoothSegmentedCurve::ValueAndSlope SmoothSegmentedCurve::ValueAndDerivative(double x) const {
  CheckBuilt();
  if (x < x0_) return {y0_ + dydx0_ * (x - x0_), dydx0_};
  if (x > x1_) return {y1_ + dydx1_ * (x - x1_), dydx1_};
  const SegmentParameter at = Locate(x);
  const Polynomials& poly = polynomials_[at.segment];
  const PolynomialDerivatives xu = EvalPolynomial(poly.x, at.u);
  const PolynomialDerivatives yu = EvalPolynomial(poly.y, at.u);
  return {yu.value, yu.d1 / xu.d1};
}

double SmoothSegmentedCurve::SegmentIntegral(int s, double u) const {
  // y(v) x'(v) is a polynomial of degree 9 in v: 5-point Gauss-Legendre on [0, u] is exact.
  static constexpr std::array<double, 5> kNodes = {0.0, -0.5384693101056831, 0.5384693101056831,
                                                   -0.9061798459386640, 0.9061798459386640};
  static constexpr std::array<double, 5> kWeights = {0.5688888888888889, 0.4786286704993665,
                                                     0.4786286704993665, 0.2369268850561891,
                                                     0.2369268850561891};
  const Polynomials& poly = polynomials_[s];
  double sum = 0.0;
  for (int k = 0; k < 5; ++k) {
    const double v = 0.5 * u * (kNodes[k] + 1.0);
    sum += kWeights[k] * PolynomialValue(poly.y, v) * EvalPolynomial(poly.x, v).d1;
  }
  return 0.5 * u * sum;
}

double SmoothSegmentedCurve::Integral(double x) const {
  CheckBuilt();
  if (x <= x0_) return (x - x0_) * (y0_ + 0.5 * dydx0_ * (x - x0_));
  const double x_in = std::min(x, x1_);
  const SegmentParameter at = Locate(x_in);
  double integral = SegmentIntegral(at.segment, at.u);
  for (int s = 0; s < at.segment; ++s) integral += SegmentIntegral(s, 1.0);
  if (x > x1_) integral += (x - x1_) * (y1_ + 0.5 * dydx1_ * (x - x1_));
  return integral;
}

}  // namespace sinew::muscles

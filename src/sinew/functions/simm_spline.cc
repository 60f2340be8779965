#include <sinew/functions/derivative_order.h>
#include <sinew/functions/knots.h>
#include <sinew/functions/simm_spline.h>

#include <algorithm>
#include <cmath>

namespace sinew::functions {
namespace {

// OpenSim's smallest knot spacing (SimmMacros' TINY_NUMBER).
constexpr double kMinSpacing = 1e-7;

double Spacing(double from, double to) { return std::max(kMinSpacing, to - from); }

}  // namespace

SimmSpline::SimmSpline(std::vector<double> x, std::vector<double> y)
    : x_(std::move(x)), y_(std::move(y)) {
  CheckKnots(x_, y_, 2, "SimmSpline");
  CalcCoefficients();
}

// Solves for sigma_i = s''(x_i)/2 with a tridiagonal system whose interior rows are the usual
// C2 continuity conditions, scaled, and whose end rows fix the end third derivatives to those
// of the cubic through the four end knots (FMM). b holds the diagonal, d the off-diagonal
// (the spacings h_i), c the right-hand side, then the solution.
void SimmSpline::CalcCoefficients() {
  const int n = static_cast<int>(x_.size());
  b_.assign(n, 0.0);
  c_.assign(n, 0.0);
  d_.assign(n, 0.0);
  if (n == 2) {
    b_[0] = b_[1] = (y_[1] - y_[0]) / Spacing(x_[0], x_[1]);
    return;
  }
  const int last = n - 1;
  // Interior rows: h_{i-1} s_{i-1} + 2 (h_{i-1} + h_i) s_i + h_i s_{i+1} = delta_i - delta_{i-1},
  // with delta_i the slope of chord i.
  d_[0] = Spacing(x_[0], x_[1]);
  c_[1] = (y_[1] - y_[0]) / d_[0];
  for (int i = 1; i < last; ++i) {
    d_[i] = Spacing(x_[i], x_[i + 1]);
    b_[i] = 2.0 * (d_[i - 1] + d_[i]);
    c_[i + 1] = (y_[i + 1] - y_[i]) / d_[i];
    c_[i] = c_[i + 1] - c_[i];
  }
  // End rows: -h_0 s_0 + h_0 s_1 = h_0^2 * (third divided difference at the start), and the
  // mirror image at the end. With 3 knots the right-hand sides are 0 (a parabola).
  b_[0] = -d_[0];
  b_[last] = -d_[last - 1];
  c_[0] = 0.0;
  c_[last] = 0.0;
  if (n > 3) {
    const double start = c_[2] / Spacing(x_[1], x_[3]) - c_[1] / Spacing(x_[0], x_[2]);
    const double end =
        c_[last - 1] / Spacing(x_[n - 3], x_[last]) - c_[n - 3] / Spacing(x_[n - 4], x_[last - 1]);
    c_[0] = start * d_[0] * d_[0] / Spacing(x_[0], x_[3]);
    c_[last] = -end * d_[last - 1] * d_[last - 1] / Spacing(x_[n - 4], x_[last]);
  }
  // Gaussian elimination without pivoting (the system is diagonally dominant after the first
  // step), then back substitution.
  for (int i = 1; i < n; ++i) {
    const double t = d_[i - 1] / b_[i - 1];
    b_[i] -= t * d_[i - 1];
    c_[i] -= t * c_[i - 1];
  }
  c_[last] /= b_[last];
  for (int i = last - 1; i >= 0; --i) c_[i] = (c_[i] - d_[i] * c_[i + 1]) / b_[i];
  // Polynomial coefficients from sigma: b = slope, c = s''/2, d = s'''/6 on each interval.
  b_[last] =
      (y_[last] - y_[last - 1]) / d_[last - 1] + d_[last - 1] * (c_[last - 1] + 2.0 * c_[last]);
  for (int i = 0; i < last; ++i) {
    b_[i] = (y_[i + 1] - y_[i]) / d_[i] - d_[i] * (c_[i + 1] + 2.0 * c_[i]);
    d_[i] = (c_[i + 1] - c_[i]) / d_[i];
    c_[i] *= 3.0;
  }
  c_[last] *= 3.0;
  d_[last] = d_[last - 1];
}

double SimmSpline::Calc(double x) const {
  const int last = static_cast<int>(x_.size()) - 1;
  if (x < x_[0]) return y_[0] + (x - x_[0]) * b_[0];
  if (x > x_[last]) return y_[last] + (x - x_[last]) * b_[last];
  const int k = FindKnotInterval(x_, x);
  const double dx = x - x_[k];
  return y_[k] + dx * (b_[k] + dx * (c_[k] + dx * d_[k]));
}

double SimmSpline::CalcDerivative(double x, int order) const {
  CheckDerivativeOrder(order, "SimmSpline");
  if (order == 0) return Calc(x);
  const int last = static_cast<int>(x_.size()) - 1;
  // Linear extrapolation: constant slope, no curvature.
  if (x < x_[0]) return order == 1 ? b_[0] : 0.0;
  if (x > x_[last]) return order == 1 ? b_[last] : 0.0;
  const int k = FindKnotInterval(x_, x);
  const double dx = x - x_[k];
  if (order == 1) return b_[k] + dx * (2.0 * c_[k] + 3.0 * dx * d_[k]);
  return 2.0 * c_[k] + 6.0 * dx * d_[k];
}

// The knots where the pieces on either side differ in their third derivative (6 d; 0 on the
// lines outside), and the ends whose cubic is curved there (f'' is continuous inside).
// Differences within 1e-9 of the spline's largest f'' (or f''' over the knots' span) are
// rounding: a cubic's or a parabola's data give one cubic or parabola.
std::vector<double> SimmSpline::Breakpoints() const {
  const std::size_t last = x_.size() - 1;
  double largest_second = 0.0, largest_third = 0.0;
  for (std::size_t i = 0; i <= last; ++i) {
    largest_second = std::max(largest_second, std::abs(CalcDerivative(x_[i], 2)));
    if (i < last) largest_third = std::max(largest_third, 6.0 * std::abs(d_[i]));
  }
  const double span = std::max(kMinSpacing, x_[last] - x_[0]);
  const double second_tolerance = 1e-9 * std::max(largest_second, largest_third * span);
  std::vector<double> points;
  for (std::size_t i = 0; i <= last; ++i) {
    const double before = i == 0 ? 0.0 : 6.0 * d_[i - 1], after = i == last ? 0.0 : 6.0 * d_[i];
    const bool end = i == 0 || i == last;
    if (std::abs(before - after) * span > second_tolerance ||
        (end && std::abs(CalcDerivative(x_[i], 2)) > second_tolerance)) {
      points.push_back(x_[i]);
    }
  }
  return points;
}

}  // namespace sinew::functions

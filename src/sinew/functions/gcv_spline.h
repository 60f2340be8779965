// OpenSim's GCVSpline (Woltring's GCVSPL spline), for the interpolating case.
#pragma once

#include <sinew/functions/function.h>

#include <vector>

namespace sinew::functions {

/// Woltring's GCVSPL spline as OpenSim uses it: the natural spline of degree 2 * half_order - 1
/// with knots at x (piecewise polynomials of that degree, continuous up to derivative
/// 2 * half_order - 2, derivatives half_order .. 2 * half_order - 2 zero at both end knots;
/// outside [x[0], x[n-1]] the polynomial of degree half_order - 1 with the end derivatives, so a
/// quintic (half_order 3) extrapolates quadratically) that minimizes
///   sum_i (y_i - s(x_i))^2 + p * integral (s^(half_order))^2 dx.
/// OpenSim refits from x, y and `error_variance` (Simbody's SplineFitter over gcvspl, unit
/// weights; stored `weights` and `coefficients` do not matter) and so does this class:
/// - error_variance == 0: p = 0, interpolation. gcvspl drives p to its floor
///   (p * mean|W| < 1e-15), i.e. interpolation up to rounding.
/// - error_variance > 0 (known variance s2): p minimizes the predicted mean squared error
///   R(p) = RSS/n - s2 * (2 tr(I - A)/n - 1), A the influence matrix (gcvspl mode 3).
/// - error_variance < 0: p minimizes GCV(p) = (RSS/n) / (tr(I - A)/n)^2 (gcvspl mode 2).
/// For the smoothing modes this class searches the global minimum over 24 decades of p (grid of
/// half decades, then golden section to 1e-9 decades); gcvspl walks downhill from its own start
/// and stops at 1e-6 relative in p. Both agree when the criterion has one minimum; with several
/// they may pick different ones. The fit costs O(n) per p plus n solves for tr(A), about
/// 100 p values: fine for controls of a few hundred points, seconds for thousands.
/// Needs strictly increasing x, at least 2 * half_order points, half_order in 1..4 (OpenSim's
/// range: linear to heptic).
class GCVSpline final : public Function {
 public:
  /// Fits as OpenSim does for `error_variance` (see the class comment). Throws sinew::Error for
  /// bad knots or half_order.
  GCVSpline(int half_order, std::vector<double> x, std::vector<double> y,
            double error_variance = 0.0);

  /// The spline for a given smoothing parameter p >= 0 (0: interpolation), no search.
  static GCVSpline WithSmoothingParameter(int half_order, std::vector<double> x,
                                          std::vector<double> y, double p);

  /// The criterion the smoothing modes minimize, at smoothing parameter p: R(p) for
  /// error_variance >= 0, GCV(p) for error_variance < 0. For tests and diagnostics.
  static double CalcSmoothingCriterion(int half_order, const std::vector<double>& x,
                                       const std::vector<double>& y, double error_variance,
                                       double p);

  std::string TypeName() const override { return "GCVSpline"; }
  double Calc(double x) const override { return CalcDerivative(x, 0); }
  double CalcDerivative(double x, int order) const override;
  /// A cubic one's knots, ends included (past them it continues linearly); none for a quintic
  /// (its fourth derivative jumps, below what rk45's error control feels) or a linear one (its
  /// corners make the velocities jump, which no step can cross exactly).
  std::vector<double> Breakpoints() const override;

  int half_order() const { return half_order_; }
  /// Degree of the pieces, 2 * half_order - 1.
  int degree() const { return 2 * half_order_ - 1; }
  /// The knots and the data values, as given.
  const std::vector<double>& x() const { return x_; }
  const std::vector<double>& y() const { return y_; }
  /// The smoothing parameter p of the fit (0 for interpolation).
  double smoothing_parameter() const { return smoothing_parameter_; }

 private:
  struct FixedSmoothing {};
  GCVSpline(int half_order, std::vector<double> x, std::vector<double> y, double p, FixedSmoothing);
  void CheckInput() const;
  double ChooseSmoothingParameter(double error_variance) const;
  void Fit();
  // d^order/dx^order of the polynomial of interval k at x.
  double CalcPiece(int k, double x, int order) const;

  int half_order_;
  std::vector<double> x_, y_;
  double smoothing_parameter_ = 0.0;
  // Coefficients of interval k: coefficients_[k * (degree + 1) + j] multiplies u^j with
  // u = (x - x[k]) / (x[k+1] - x[k]).
  std::vector<double> coefficients_;
  // Derivatives 0 .. half_order-1 at the first and last knots, for extrapolation.
  std::vector<double> start_derivatives_, end_derivatives_;
};

}  // namespace sinew::functions

// OpenSim's GCVSpline (Woltring's GCVSPL spline), for the interpolating case.
#pragma once

#include <vector>

#include "functions/function.h"

namespace sinew {

/// The natural spline of degree 2 * half_order - 1 through the knots (x[i], y[i]): piecewise
/// polynomials of that degree, continuous up to derivative 2 * half_order - 2, with derivatives
/// half_order .. 2 * half_order - 2 zero at both end knots; outside [x[0], x[n-1]] it continues
/// as the polynomial of degree half_order - 1 with the end derivatives (so half_order 3, a
/// quintic, extrapolates quadratically; half_order 1 holds the end values).
///
/// OpenSim fits a GCVSpline with Woltring's gcvspl (through Simbody's SplineFitter) using the
/// stored `error_variance` (OpenSim recomputes the fit; stored `coefficients` are ignored).
/// With error_variance == 0 that fit drives the smoothing parameter p down to gcvspl's floor
/// (p * mean|W| < 1e-15), i.e. to interpolation up to rounding, which is what this class
/// computes. Smoothing fits (error_variance > 0, or < 0 for true GCV) are NOT implemented: the
/// constructor rejects them. Weights only matter for smoothing and are ignored.
/// Needs strictly increasing x, at least 2 * half_order points, half_order in 1..4 (OpenSim's
/// range: linear to heptic).
class GCVSpline final : public Function {
 public:
  /// Throws sinew::Error for bad knots, half_order, or error_variance != 0.
  GCVSpline(int half_order, std::vector<double> x, std::vector<double> y,
            double error_variance = 0.0);

  std::string TypeName() const override { return "GCVSpline"; }
  double Calc(double x) const override { return CalcDerivative(x, 0); }
  double CalcDerivative(double x, int order) const override;

  int half_order() const { return half_order_; }
  /// Degree of the pieces, 2 * half_order - 1.
  int degree() const { return 2 * half_order_ - 1; }
  const std::vector<double>& x() const { return x_; }
  const std::vector<double>& y() const { return y_; }

 private:
  // d^order/dx^order of the polynomial of interval k at x.
  double CalcPiece(int k, double x, int order) const;

  int half_order_;
  std::vector<double> x_, y_;
  // Coefficients of interval k: coefficients_[k * (degree + 1) + j] multiplies u^j with
  // u = (x - x[k]) / (x[k+1] - x[k]).
  std::vector<double> coefficients_;
  // Derivatives 0 .. half_order-1 at the first and last knots, for extrapolation.
  std::vector<double> start_derivatives_, end_derivatives_;
};

}  // namespace sinew

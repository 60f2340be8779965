// OpenSim's PiecewiseLinearFunction.
#pragma once

#include <sinew/functions/function.h>

#include <vector>

namespace sinew::functions {

/// Straight lines between the knots (x[i], y[i]); outside [x[0], x[n-1]] it extrapolates
/// linearly with the first (last) segment's slope, as OpenSim does. The first derivative is the
/// slope of the segment holding x (exactly on an interior knot: the segment OpenSim's bisection
/// picks; before x[0] the first, at and beyond x[n-1] the last); the second derivative is 0.
/// Knot spacings below 1e-7 are raised to 1e-7 (no division by zero on duplicate knots).
class PiecewiseLinearFunction final : public Function {
 public:
  /// Knots `x` (non-decreasing, >= 2 points) and values `y`; throws sinew::Error otherwise.
  PiecewiseLinearFunction(std::vector<double> x, std::vector<double> y);

  std::string TypeName() const override { return "PiecewiseLinearFunction"; }
  double Calc(double x) const override;
  double CalcDerivative(double x, int order) const override;

  /// The knots and the data values, as given.
  const std::vector<double>& x() const { return x_; }
  const std::vector<double>& y() const { return y_; }

 private:
  std::vector<double> x_, y_;
  std::vector<double> slope_;  // slope_[k] of segment k; slope_[n-1] = slope_[n-2]
};

}  // namespace sinew::functions

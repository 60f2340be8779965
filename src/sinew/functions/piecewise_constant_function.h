// OpenSim's PiecewiseConstantFunction.
#pragma once

#include <sinew/functions/function.h>

#include <vector>

namespace sinew::functions {

/// A staircase through the knots, as OpenSim evaluates it: f = y[0] for x <= x[0],
/// f = y[n-1] for x >= x[n-1], and f = y[k] for x in (x[k], x[k+1]), i.e. each value holds
/// from its knot up to the next one. Exactly on an interior knot x[k] the value is y[k] or
/// y[k-1], whichever OpenSim's bisection lands on (reproduced here). Derivatives are 0.
class PiecewiseConstantFunction final : public Function {
 public:
  /// Knots `x` (non-decreasing, >= 1 point) and values `y`; throws sinew::Error otherwise.
  PiecewiseConstantFunction(std::vector<double> x, std::vector<double> y);

  std::string TypeName() const override { return "PiecewiseConstantFunction"; }
  double Calc(double x) const override;
  double CalcDerivative(double x, int order) const override;

  /// The knots and the data values, as given.
  const std::vector<double>& x() const { return x_; }
  const std::vector<double>& y() const { return y_; }

 private:
  std::vector<double> x_, y_;
};

}  // namespace sinew::functions

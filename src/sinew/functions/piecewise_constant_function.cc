#include <sinew/functions/derivative_order.h>
#include <sinew/functions/knots.h>
#include <sinew/functions/piecewise_constant_function.h>

#include <cmath>

namespace sinew::functions {

PiecewiseConstantFunction::PiecewiseConstantFunction(std::vector<double> x, std::vector<double> y)
    : x_(std::move(x)), y_(std::move(y)) {
  CheckKnots(x_, y_, 1, "PiecewiseConstantFunction");
}

double PiecewiseConstantFunction::Calc(double x) const {
  const size_t last = x_.size() - 1;
  if (std::isnan(x)) return x;
  if (x <= x_[0]) return y_[0];
  if (x >= x_[last]) return y_[last];
  return y_[FindKnotInterval(x_, x)];
}

double PiecewiseConstantFunction::CalcDerivative(double x, int order) const {
  CheckDerivativeOrder(order, "PiecewiseConstantFunction");
  return order == 0 ? Calc(x) : 0.0;
}

}  // namespace sinew::functions

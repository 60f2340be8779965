#include <sinew/functions/derivative_order.h>
#include <sinew/functions/knots.h>
#include <sinew/functions/piecewise_linear_function.h>

#include <algorithm>

namespace sinew::functions {

PiecewiseLinearFunction::PiecewiseLinearFunction(std::vector<double> x, std::vector<double> y)
    : x_(std::move(x)), y_(std::move(y)) {
  CheckKnots(x_, y_, 2, "PiecewiseLinearFunction");
  const size_t n = x_.size();
  slope_.resize(n);
  for (size_t i = 0; i + 1 < n; ++i) {
    slope_[i] = (y_[i + 1] - y_[i]) / std::max(1e-7, x_[i + 1] - x_[i]);
  }
  slope_[n - 1] = slope_[n - 2];
}

double PiecewiseLinearFunction::Calc(double x) const {
  const int last = static_cast<int>(x_.size()) - 1;
  if (x < x_[0]) return y_[0] + (x - x_[0]) * slope_[0];
  if (x > x_[last]) return y_[last] + (x - x_[last]) * slope_[last];
  const int k = FindKnotInterval(x_, x);
  return y_[k] + (x - x_[k]) * slope_[k];
}

double PiecewiseLinearFunction::CalcDerivative(double x, int order) const {
  CheckDerivativeOrder(order, "PiecewiseLinearFunction");
  if (order == 0) return Calc(x);
  if (order == 2) return 0.0;
  return slope_[FindKnotInterval(x_, x)];
}

}  // namespace sinew::functions

#include <sinew/common/error.h>
#include <sinew/functions/derivative_order.h>
#include <sinew/functions/excitations.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sinew::functions {

double Ramp::Calc(double t) const { return t < start_ ? 0.0 : slope_ * (t - start_); }

double Ramp::CalcDerivative(double t, int order) const {
  CheckDerivativeOrder(order, "Ramp");
  if (order == 0) return Calc(t);
  if (order == 2) return 0.0;
  return t < start_ ? 0.0 : slope_;
}

double SineExcitation::Calc(double t) const { return CalcDerivative(t, 0); }

double SineExcitation::CalcDerivative(double t, int order) const {
  CheckDerivativeOrder(order, "SineExcitation");
  const double omega = 2.0 * std::numbers::pi * frequency_hz_;
  const double angle = omega * t + phase_;
  switch (order) {
    case 0:
      return amplitude_ * std::sin(angle) + offset_;
    case 1:
      return amplitude_ * omega * std::cos(angle);
    default:
      return -amplitude_ * omega * omega * std::sin(angle);
  }
}

CallableFunction::CallableFunction(std::function<double(double)> function, std::string name)
    : function_(std::move(function)), name_(std::move(name)) {
  if (!function_) throw Error("CallableFunction: the callable is empty");
}

double CallableFunction::CalcDerivative(double x, int order) const {
  CheckDerivativeOrder(order, name_);
  const double scale = std::max(1.0, std::abs(x));
  if (order == 0) return function_(x);
  if (order == 1) {
    const double h = 6e-6 * scale;
    return (function_(x + h) - function_(x - h)) / (2.0 * h);
  }
  const double h = 1.2e-4 * scale;
  return (function_(x + h) - 2.0 * function_(x) + function_(x - h)) / (h * h);
}

}  // namespace sinew::functions

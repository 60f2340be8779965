#include <sinew/functions/derivative_order.h>
#include <sinew/functions/sine.h>

#include <cmath>

namespace sinew::functions {

double Sine::Calc(double x) const { return amplitude_ * std::sin(omega_ * x + phase_) + offset_; }

double Sine::CalcDerivative(double x, int order) const {
  CheckDerivativeOrder(order, "Sine");
  const double angle = omega_ * x + phase_;
  switch (order) {
    case 0:
      return Calc(x);
    case 1:
      return amplitude_ * omega_ * std::cos(angle);
    default:
      return -amplitude_ * omega_ * omega_ * std::sin(angle);
  }
}

}  // namespace sinew::functions

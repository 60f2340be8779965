#include <sinew/functions/constant.h>
#include <sinew/functions/derivative_order.h>

namespace sinew::functions {

double Constant::CalcDerivative(double /*x*/, int order) const {
  CheckDerivativeOrder(order, "Constant");
  return order == 0 ? value_ : 0.0;
}

double Constant::CalcPartialN(std::span<const double> /*x*/, std::span<const int> wrt) const {
  CheckDerivativeOrder(static_cast<int>(wrt.size()), "Constant");
  return wrt.empty() ? value_ : 0.0;
}

}  // namespace sinew::functions

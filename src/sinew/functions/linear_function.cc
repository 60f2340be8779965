#include <sinew/functions/derivative_order.h>
#include <sinew/functions/linear_function.h>

namespace sinew::functions {

double LinearFunction::CalcDerivative(double x, int order) const {
  CheckDerivativeOrder(order, "LinearFunction");
  if (order == 0) return Calc(x);
  return order == 1 ? slope_ : 0.0;
}

}  // namespace sinew::functions

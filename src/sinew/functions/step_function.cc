#include <sinew/common/error.h>
#include <sinew/functions/derivative_order.h>
#include <sinew/functions/step_function.h>

namespace sinew::functions {

StepFunction::StepFunction(double transition_start_time, double transition_end_time,
                           double start_value, double end_value)
    : x0_(transition_start_time), x1_(transition_end_time), y0_(start_value), y1_(end_value) {
  if (!(x0_ != x1_)) {
    throw Error("StepFunction: transition_start_time and transition_end_time must differ (both " +
                std::to_string(x0_) + ")");
  }
}

double StepFunction::CalcDerivative(double x, int order) const {
  CheckDerivativeOrder(order, "StepFunction");
  const double inverse_width = 1.0 / (x1_ - x0_);
  const double s = (x - x0_) * inverse_width;
  // Before the transition (s <= 0) and after it (s >= 1) the step is flat.
  if (s <= 0.0) return order == 0 ? y0_ : 0.0;
  if (s >= 1.0) return order == 0 ? y1_ : 0.0;
  const double rise = y1_ - y0_;
  switch (order) {
    case 0:  // 10 s^3 - 15 s^4 + 6 s^5
      return y0_ + rise * s * s * s * (10.0 + s * (-15.0 + 6.0 * s));
    case 1:  // 30 s^2 (1 - s)^2, times ds/dx
      return rise * 30.0 * s * s * (1.0 - s) * (1.0 - s) * inverse_width;
    default:  // 60 s (1 - s)(1 - 2 s), times (ds/dx)^2
      return rise * 60.0 * s * (1.0 - s) * (1.0 - 2.0 * s) * inverse_width * inverse_width;
  }
}

}  // namespace sinew::functions

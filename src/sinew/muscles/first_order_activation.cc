#include <sinew/muscles/first_order_activation.h>

#include <algorithm>

namespace sinew::muscles {

double FirstOrderActivation::Clamp(double activation) const {
  return std::clamp(activation, minimum_activation, 1.0);
}

double FirstOrderActivation::CalcDerivative(double activation, double excitation) const {
  const double a = Clamp(activation);
  const double tau = excitation > a ? activation_time_constant * (0.5 + 1.5 * a)
                                    : deactivation_time_constant / (0.5 + 1.5 * a);
  return (excitation - a) / tau;
}

}  // namespace sinew::muscles

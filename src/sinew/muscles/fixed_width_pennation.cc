#include <sinew/common/error.h>
#include <sinew/muscles/fixed_width_pennation.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sinew::muscles {

FixedWidthPennation::FixedWidthPennation(double optimal_fiber_length,
                                         double pennation_angle_at_optimal,
                                         double maximum_pennation_angle)
    : pennation_at_optimal_(pennation_angle_at_optimal),
      maximum_pennation_(maximum_pennation_angle) {
  if (!(optimal_fiber_length > 0.0)) {
    throw Error(SourceLocation{}, "", "optimal_fiber_length must be greater than zero");
  }
  if (!(pennation_angle_at_optimal >= 0.0 && pennation_angle_at_optimal < std::numbers::pi / 2)) {
    throw Error(SourceLocation{}, "", "pennation_angle_at_optimal must be in [0, pi/2)");
  }
  if (!(maximum_pennation_angle >= 0.0 && maximum_pennation_angle <= std::numbers::pi / 2)) {
    throw Error(SourceLocation{}, "", "maximum_pennation_angle must be in [0, pi/2]");
  }
  height_ = optimal_fiber_length * std::sin(pennation_angle_at_optimal);
  maximum_sin_ = std::sin(maximum_pennation_angle);
  // OpenSim's rule: a muscle that may not pennate may still shorten to 1% of its optimum.
  minimum_fiber_length_ =
      maximum_pennation_angle > 1e-14 ? height_ / maximum_sin_ : 0.01 * optimal_fiber_length;
}

double FixedWidthPennation::ClampFiberLength(double fiber_length) const {
  return std::max(fiber_length, minimum_fiber_length_);
}

double FixedWidthPennation::PennationAngle(double fiber_length) const {
  if (!(pennation_at_optimal_ > 2.3e-16)) return 0.0;
  if (fiber_length <= minimum_fiber_length_) return maximum_pennation_;
  const double sin_phi = height_ / fiber_length;
  return sin_phi < maximum_sin_ ? std::asin(sin_phi) : maximum_pennation_;
}

double FixedWidthPennation::FiberLength(double muscle_length, double tendon_length) const {
  const double along_tendon = muscle_length - tendon_length;
  if (along_tendon < minimum_fiber_length_ * std::cos(maximum_pennation_)) {
    return minimum_fiber_length_;
  }
  return std::sqrt(height_ * height_ + along_tendon * along_tendon);
}

}  // namespace sinew::muscles

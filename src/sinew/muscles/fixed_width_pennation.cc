#include <sinew/common/error.h>
#include <sinew/muscles/fixed_width_pennation.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace sinew::muscles {

namespace {
// Simbody's SignificantReal, eps^(7/8): OpenSim's threshold for "zero" in these models.
const double kSignificantReal = std::pow(std::numeric_limits<double>::epsilon(), 0.875);
}  // namespace

FixedWidthPennation::FixedWidthPennation(double optimal_fiber_length,
                                         double pennation_angle_at_optimal,
                                         double maximum_pennation_angle)
    : pennation_at_optimal_(pennation_angle_at_optimal), maximum_angle_(maximum_pennation_angle) {
  const double half_pi = 0.5 * std::numbers::pi;
  if (!(optimal_fiber_length > 0.0)) throw Error("optimal_fiber_length must be greater than 0");
  if (!(pennation_angle_at_optimal >= 0.0 &&
        pennation_angle_at_optimal <= half_pi - kSignificantReal)) {
    throw Error("pennation_angle_at_optimal must be in [0, pi/2)");
  }
  if (!(maximum_pennation_angle >= 0.0 && maximum_pennation_angle <= half_pi)) {
    throw Error("maximum_pennation_angle must be in [0, pi/2]");
  }
  height_ = optimal_fiber_length * std::sin(pennation_angle_at_optimal);
  maximum_sin_ = std::sin(maximum_pennation_angle);
  minimum_fiber_length_ = maximum_pennation_angle > kSignificantReal ? height_ / maximum_sin_
                                                                     : 0.01 * optimal_fiber_length;
  minimum_along_tendon_ = minimum_fiber_length_ * std::cos(maximum_pennation_angle);
}

double FixedWidthPennation::ClampFiberLength(double fiber_length) const {
  return std::max(fiber_length, minimum_fiber_length_);
}

double FixedWidthPennation::PennationAngle(double fiber_length) const {
  if (!(pennation_at_optimal_ > std::numeric_limits<double>::epsilon())) return 0.0;
  if (!(fiber_length > minimum_fiber_length_)) return maximum_angle_;
  const double sin_phi = height_ / fiber_length;
  return sin_phi < maximum_sin_ ? std::asin(sin_phi) : maximum_angle_;
}

double FixedWidthPennation::FiberLength(double muscle_length, double tendon_length) const {
  const double along_tendon = muscle_length - tendon_length;
  if (!(along_tendon >= minimum_along_tendon_)) return minimum_fiber_length_;
  return std::sqrt(height_ * height_ + along_tendon * along_tendon);
}

double FixedWidthPennation::DPennationAngleDFiberLength(double fiber_length) const {
  const double h_over_l = height_ / fiber_length;
  return (-h_over_l / fiber_length) / std::sqrt(1.0 - h_over_l * h_over_l);
}

double FixedWidthPennation::PennationAngularVelocity(double tan_phi, double fiber_length,
                                                     double fiber_velocity) const {
  if (!(pennation_at_optimal_ > std::numeric_limits<double>::epsilon())) return 0.0;
  return -(fiber_velocity / fiber_length) * tan_phi;
}

}  // namespace sinew::muscles

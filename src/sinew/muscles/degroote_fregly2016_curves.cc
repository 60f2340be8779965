#include <sinew/common/error.h>
#include <sinew/muscles/degroote_fregly2016_curves.h>

#include <array>
#include <cmath>

namespace sinew::muscles {

namespace {

// The paper's coefficients: active force-length (three Gaussian-like terms b1..b4), force-
// velocity (d1..d4), passive (kPE, minimum normalized fiber length) and tendon (c1..c3).
struct GaussianTerm {
  double b1, b2, b3, b4;
};
constexpr std::array<GaussianTerm, 3> kActiveTerms = {{
    {0.8150671134243542, 1.055033428970575, 0.162384573599574, 0.063303448465465},
    {0.433004984392647, 0.716775413397760, -0.029947116970696, 0.200356847296188},
    {0.1, 1.0, 0.353553390593274, 0.0},  // b3 = 0.5 sqrt(0.5)
}};
constexpr double kD1 = -0.3211346127989808, kD2 = -8.149, kD3 = -0.374, kD4 = 0.8825327733249912;
constexpr double kPE = 4.0;
constexpr double kMinNormFiberLength = 0.2;
constexpr double kC1 = 0.2, kC2 = 1.0, kC3 = 0.2;

}  // namespace

DeGrooteFregly2016Curves::DeGrooteFregly2016Curves(double active_force_width_scale,
                                                   double passive_fiber_strain_at_one_norm_force,
                                                   double tendon_strain_at_one_norm_force,
                                                   bool ignore_passive_fiber_force)
    : width_scale_(active_force_width_scale),
      passive_strain_(passive_fiber_strain_at_one_norm_force),
      ignore_passive_(ignore_passive_fiber_force) {
  if (!(active_force_width_scale >= 1.0)) {
    throw Error("active_force_width_scale must be at least 1");
  }
  if (!(passive_fiber_strain_at_one_norm_force > 0.0)) {
    throw Error("passive_fiber_strain_at_one_norm_force must be greater than 0");
  }
  if (!(tendon_strain_at_one_norm_force > 0.0)) {
    throw Error("tendon_strain_at_one_norm_force must be greater than 0");
  }
  k_tendon_ = std::log((1.0 + kC3) / kC1) / (1.0 + tendon_strain_at_one_norm_force - kC2);
}

double DeGrooteFregly2016Curves::ActiveForceLength(double norm_fiber_length) const {
  const double x = (norm_fiber_length - 1.0) / width_scale_ + 1.0;
  double sum = 0.0;
  for (const GaussianTerm& t : kActiveTerms) {
    const double width = t.b3 + t.b4 * x;
    sum += t.b1 * std::exp(-0.5 * (x - t.b2) * (x - t.b2) / (width * width));
  }
  return sum;
}

double DeGrooteFregly2016Curves::ActiveForceLengthDerivative(double norm_fiber_length) const {
  const double x = (norm_fiber_length - 1.0) / width_scale_ + 1.0;
  double sum = 0.0;
  for (const GaussianTerm& t : kActiveTerms) {
    // d/dx of b1 exp(-g) with g = (x - b2)^2 / (2 w^2), w = b3 + b4 x:
    // -b1 exp(-g) (x - b2) (b3 + b2 b4) / w^3.
    const double width = t.b3 + t.b4 * x;
    const double g = 0.5 * (x - t.b2) * (x - t.b2) / (width * width);
    sum += -t.b1 * std::exp(-g) * (x - t.b2) * (t.b3 + t.b2 * t.b4) / (width * width * width);
  }
  return sum / width_scale_;
}

double DeGrooteFregly2016Curves::ForceVelocity(double norm_fiber_velocity) {
  const double w = kD2 * norm_fiber_velocity + kD3;
  return kD1 * std::log(w + std::sqrt(w * w + 1.0)) + kD4;
}

double DeGrooteFregly2016Curves::ForceVelocityDerivative(double norm_fiber_velocity) {
  const double w = kD2 * norm_fiber_velocity + kD3;
  return kD1 * kD2 / std::sqrt(w * w + 1.0);
}

double DeGrooteFregly2016Curves::ForceVelocityInverse(double force_velocity_multiplier) {
  return (std::sinh((force_velocity_multiplier - kD4) / kD1) - kD3) / kD2;
}

double DeGrooteFregly2016Curves::PassiveForceLength(double norm_fiber_length) const {
  if (ignore_passive_) return 0.0;
  const double offset = std::exp(kPE * (kMinNormFiberLength - 1.0) / passive_strain_);
  return (std::exp(kPE * (norm_fiber_length - 1.0) / passive_strain_) - offset) /
         (std::exp(kPE) - offset);
}

double DeGrooteFregly2016Curves::PassiveForceLengthDerivative(double norm_fiber_length) const {
  if (ignore_passive_) return 0.0;
  const double offset = std::exp(kPE * (kMinNormFiberLength - 1.0) / passive_strain_);
  return kPE / passive_strain_ * std::exp(kPE * (norm_fiber_length - 1.0) / passive_strain_) /
         (std::exp(kPE) - offset);
}

double DeGrooteFregly2016Curves::PassiveForceLengthIntegral(double norm_fiber_length) const {
  if (ignore_passive_) return 0.0;
  const double offset = std::exp(kPE * (kMinNormFiberLength - 1.0) / passive_strain_);
  const double exponential = passive_strain_ / kPE *
                             (std::exp(kPE * (norm_fiber_length - 1.0) / passive_strain_) - offset);
  return (exponential - offset * (norm_fiber_length - kMinNormFiberLength)) /
         (std::exp(kPE) - offset);
}

double DeGrooteFregly2016Curves::TendonForceLength(double norm_tendon_length) const {
  return kC1 * std::exp(k_tendon_ * (norm_tendon_length - kC2)) - kC3;
}

double DeGrooteFregly2016Curves::TendonForceLengthDerivative(double norm_tendon_length) const {
  return kC1 * k_tendon_ * std::exp(k_tendon_ * (norm_tendon_length - kC2));
}

double DeGrooteFregly2016Curves::TendonForceLengthInverse(double norm_tendon_force) const {
  return std::log((norm_tendon_force + kC3) / kC1) / k_tendon_ + kC2;
}

double DeGrooteFregly2016Curves::TendonForceLengthIntegral(double norm_tendon_length) const {
  const double slack = TendonForceLengthInverse(0.0);
  return kC1 / k_tendon_ *
             (std::exp(k_tendon_ * (norm_tendon_length - kC2)) -
              std::exp(k_tendon_ * (slack - kC2))) -
         kC3 * (norm_tendon_length - slack);
}

}  // namespace sinew::muscles

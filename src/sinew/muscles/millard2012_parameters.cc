#include <sinew/common/error.h>
#include <sinew/muscles/millard2012_parameters.h>

#include <algorithm>
#include <cstdio>
#include <limits>

namespace sinew::muscles {

namespace {

constexpr double kMinNonzeroDamping = 0.001;  // OpenSim's MIN_NONZERO_DAMPING_COEFFICIENT

std::string Update(const char* model, const char* what, double was, double now) {
  char text[200];
  std::snprintf(text, sizeof(text), "parameter update for the %s model: %s was %g but is now %g",
                model, what, was, now);
  return text;
}

// The muscle's parameters after OpenSim's adjustments, which are recorded in `notes`.
Millard2012Parameters Adjusted(Millard2012Parameters p, bool use_damping,
                               std::vector<std::string>* notes) {
  auto fail = [](const std::string& what) { throw Error(what); };
  ForceVelocityCurveParameters& fv = p.force_velocity;
  const double sqrt_eps = std::sqrt(std::numeric_limits<double>::epsilon());
  if (fv.concentric_slope_near_vmax < sqrt_eps) {
    fail("ForceVelocityCurve concentric_slope_near_vmax cannot be less than 1.49e-8");
  }
  if (fv.eccentric_slope_near_vmax < sqrt_eps) {
    fail("ForceVelocityCurve eccentric_slope_near_vmax cannot be less than 1.49e-8");
  }
  const double min_control = p.min_control.value_or(p.minimum_activation);
  if (!p.ignore_tendon_compliance && !use_damping) {
    constexpr const char* kModel = "classic Hill";
    if (p.minimum_activation > 1.0) fail("minimum_activation cannot be greater than 1");
    if (p.minimum_activation < 0.01) {
      fail(
          "minimum_activation cannot be less than 0.01 with an elastic tendon and no fiber "
          "damping (the fiber velocity is singular at activation 0)");
    }
    if (p.active_force_length.minimum_value < 0.1) {
      notes->push_back(Update(kModel, "ActiveForceLengthCurve minimum_value",
                              p.active_force_length.minimum_value, 0.1));
      p.active_force_length.minimum_value = 0.1;
    }
    if (fv.concentric_slope_at_vmax < 0.5 * fv.concentric_slope_near_vmax) {
      notes->push_back(Update(kModel, "ForceVelocityCurve concentric_slope_at_vmax",
                              fv.concentric_slope_at_vmax, 0.5 * fv.concentric_slope_near_vmax));
      fv.concentric_slope_at_vmax = 0.5 * fv.concentric_slope_near_vmax;
    }
    if (fv.eccentric_slope_at_vmax < 0.5 * fv.eccentric_slope_near_vmax) {
      notes->push_back(Update(kModel, "ForceVelocityCurve eccentric_slope_at_vmax",
                              fv.eccentric_slope_at_vmax, 0.5 * fv.eccentric_slope_near_vmax));
      fv.eccentric_slope_at_vmax = 0.5 * fv.eccentric_slope_near_vmax;
    }
  } else {
    constexpr const char* kModel = "damped";
    if (p.minimum_activation > 1.0) {
      notes->push_back(Update(kModel, "minimum_activation", p.minimum_activation, 1.0));
      p.minimum_activation = 1.0;
    }
    if (p.active_force_length.minimum_value > 0.0) {
      notes->push_back(Update(kModel, "ActiveForceLengthCurve minimum_value",
                              p.active_force_length.minimum_value, 0.0));
      p.active_force_length.minimum_value = 0.0;
    }
    if (fv.concentric_slope_at_vmax > 0.0) {
      notes->push_back(Update(kModel, "ForceVelocityCurve concentric_slope_at_vmax",
                              fv.concentric_slope_at_vmax, 0.0));
      fv.concentric_slope_at_vmax = 0.0;
    }
    if (fv.eccentric_slope_at_vmax > 0.0) {
      notes->push_back(Update(kModel, "ForceVelocityCurve eccentric_slope_at_vmax",
                              fv.eccentric_slope_at_vmax, 0.0));
      fv.eccentric_slope_at_vmax = 0.0;
    }
    if (p.minimum_activation < 0.0) fail("minimum_activation cannot be less than 0");
  }
  if (min_control < p.minimum_activation) {
    fail("min_control cannot be less than minimum_activation");
  }
  if (!(p.activation_time_constant > 0.0) || !(p.deactivation_time_constant > 0.0)) {
    fail("activation_time_constant and deactivation_time_constant must be greater than 0");
  }
  if (!(p.max_isometric_force > 0.0)) fail("max_isometric_force must be greater than 0");
  // A rigid tendon may have length 0 (ThoracoscapularShoulderModel's do); an elastic one needs a
  // length to be normalized by.
  if (!(p.tendon_slack_length > 0.0) &&
      !(p.ignore_tendon_compliance && p.tendon_slack_length == 0.0)) {
    fail("tendon_slack_length must be greater than 0 (or 0 with ignore_tendon_compliance)");
  }
  if (!(p.max_contraction_velocity > 0.0)) fail("max_contraction_velocity must be greater than 0");
  return p;
}

}  // namespace

Millard2012Muscle::Millard2012Muscle(const Millard2012Parameters& parameters)
    : use_damping_(parameters.fiber_damping >= kMinNonzeroDamping),
      pennation_(parameters.optimal_fiber_length, parameters.pennation_angle_at_optimal,
                 parameters.maximum_pennation_angle) {
  p_ = Adjusted(parameters, use_damping_, &adjustments_);
  if (!use_damping_) p_.fiber_damping = 0.0;
  // The inverse force-velocity curve always has nonzero end slopes: half those near vmax.
  ForceVelocityCurveParameters inverse = p_.force_velocity;
  inverse.concentric_slope_at_vmax = 0.5 * inverse.concentric_slope_near_vmax;
  inverse.eccentric_slope_at_vmax = 0.5 * inverse.eccentric_slope_near_vmax;
  active_force_length_ = MakeActiveForceLengthCurve(p_.active_force_length);
  force_velocity_ = MakeForceVelocityCurve(p_.force_velocity);
  force_velocity_inverse_ = MakeForceVelocityInverseCurve(inverse);
  fiber_force_length_ = MakeFiberForceLengthCurve(p_.fiber_force_length);
  tendon_force_length_ = MakeTendonForceLengthCurve(p_.tendon_force_length);
  const double min_active =
      p_.active_force_length.min_norm_active_fiber_length * p_.optimal_fiber_length;
  minimum_fiber_length_ = std::max(std::pow(std::numeric_limits<double>::epsilon(), 0.875),
                                   std::max(min_active, pennation_.minimum_fiber_length()));
}

double Millard2012Muscle::ClampFiberLength(double fiber_length) const {
  return std::max(fiber_length, minimum_fiber_length_);
}

double Millard2012Muscle::ClampActivation(double activation) const {
  return std::clamp(activation, p_.minimum_activation, 1.0);
}

}  // namespace sinew::muscles

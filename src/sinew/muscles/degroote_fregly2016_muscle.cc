#include <sinew/common/error.h>
#include <sinew/muscles/degroote_fregly2016_muscle.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

namespace sinew::muscles {

namespace {

[[noreturn]] void Fail(const DeGrooteFregly2016Muscle& m, const std::string& what) {
  throw Error(m.parameters().name + ": " + what);
}

DeGrooteFregly2016Curves MakeCurves(const DeGrooteFregly2016Parameters& p) {
  return DeGrooteFregly2016Curves(p.active_force_width_scale,
                                  p.passive_fiber_strain_at_one_norm_force,
                                  p.tendon_strain_at_one_norm_force, p.ignore_passive_fiber_force);
}

}  // namespace

DeGrooteFregly2016Muscle::DeGrooteFregly2016Muscle(const DeGrooteFregly2016Parameters& parameters)
    : p_(parameters), curves_(MakeCurves(parameters)) {
  const double significant = std::pow(std::numeric_limits<double>::epsilon(), 0.875);
  auto require = [](bool holds, const char* what) {
    if (!holds) throw Error(what);
  };
  require(p_.max_isometric_force > 0.0, "max_isometric_force must be greater than 0");
  require(p_.optimal_fiber_length > 0.0, "optimal_fiber_length must be greater than 0");
  require(p_.tendon_slack_length > 0.0, "tendon_slack_length must be greater than 0");
  require(p_.max_contraction_velocity > 0.0, "max_contraction_velocity must be greater than 0");
  require(p_.activation_time_constant > 0.0, "activation_time_constant must be greater than 0");
  require(p_.deactivation_time_constant > 0.0, "deactivation_time_constant must be greater than 0");
  require(p_.default_activation > 0.0, "default_activation must be greater than 0");
  require(p_.default_normalized_tendon_force >= 0.0 && p_.default_normalized_tendon_force <= 5.0,
          "default_normalized_tendon_force must be in [0, 5]");
  require(p_.fiber_damping >= 0.0, "fiber_damping must be at least 0");
  require(p_.activation_dynamics_smoothing > 0.0,
          "activation_dynamics_smoothing must be greater than 0");
  require(p_.pennation_angle_at_optimal >= 0.0 &&
              p_.pennation_angle_at_optimal <= 0.5 * std::numbers::pi - significant,
          "pennation_angle_at_optimal must be in [0, pi/2)");
  require(p_.tendon_compliance_dynamics_mode == "explicit" ||
              p_.tendon_compliance_dynamics_mode == "implicit",
          "tendon_compliance_dynamics_mode must be 'explicit' or 'implicit'");
  explicit_ = p_.tendon_compliance_dynamics_mode == "explicit";
  width_ = p_.optimal_fiber_length * std::sin(p_.pennation_angle_at_optimal);
}

DeGrooteFregly2016Dynamics CalcDeGrooteFregly2016Dynamics(
    const DeGrooteFregly2016Muscle& m, double activation, double norm_tendon_force,
    double path_length, double path_lengthening_speed,
    std::optional<double> norm_tendon_force_derivative) {
  const DeGrooteFregly2016Parameters& p = m.parameters();
  const DeGrooteFregly2016Curves& c = m.curves();
  const bool rigid = p.ignore_tendon_compliance;
  if (!std::isfinite(activation) || !std::isfinite(path_length) ||
      !std::isfinite(path_lengthening_speed) || (!rigid && !std::isfinite(norm_tendon_force))) {
    Fail(m, "activation, normalized tendon force, path length and speed must be finite");
  }
  const double fiso = p.max_isometric_force, lopt = p.optimal_fiber_length;
  const double vmax = p.max_contraction_velocity * lopt;  // m/s
  DeGrooteFregly2016Dynamics d;

  // Lengths: the tendon from its force, the fiber from what the tendon leaves of the path.
  d.norm_tendon_length = rigid ? 1.0 : c.TendonForceLengthInverse(norm_tendon_force);
  d.tendon_length = p.tendon_slack_length * d.norm_tendon_length;
  d.fiber_length_along_tendon = path_length - d.tendon_length;
  d.fiber_length = std::hypot(d.fiber_length_along_tendon, m.fiber_width());
  d.norm_fiber_length = d.fiber_length / lopt;
  d.cos_pennation = d.fiber_length_along_tendon / d.fiber_length;
  d.sin_pennation = m.fiber_width() / d.fiber_length;
  d.pennation_angle = std::asin(d.sin_pennation);
  d.passive_force_length_multiplier = c.PassiveForceLength(d.norm_fiber_length);
  d.active_force_length_multiplier = c.ActiveForceLength(d.norm_fiber_length);

  // Velocities.
  if (!rigid && !norm_tendon_force_derivative) {
    const double denominator = activation * d.active_force_length_multiplier;
    if (!(std::abs(denominator) > 0.0) || !(d.cos_pennation > 0.0)) {
      Fail(m,
           "the explicit tendon dynamics are singular at zero activation, zero active "
           "force-length multiplier or 90 degrees pennation");
    }
    d.force_velocity_multiplier =
        (norm_tendon_force / d.cos_pennation - d.passive_force_length_multiplier) / denominator;
    d.norm_fiber_velocity =
        DeGrooteFregly2016Curves::ForceVelocityInverse(d.force_velocity_multiplier);
    d.fiber_velocity = d.norm_fiber_velocity * vmax;
    d.fiber_velocity_along_tendon = d.fiber_velocity / d.cos_pennation;
    d.tendon_velocity = path_lengthening_speed - d.fiber_velocity_along_tendon;
    d.norm_tendon_velocity = d.tendon_velocity / p.tendon_slack_length;
    d.norm_tendon_force_derivative =
        d.norm_tendon_velocity * c.TendonForceLengthDerivative(d.norm_tendon_length);
  } else {
    if (!rigid) {
      d.norm_tendon_force_derivative = *norm_tendon_force_derivative;
      d.norm_tendon_velocity =
          d.norm_tendon_force_derivative / c.TendonForceLengthDerivative(d.norm_tendon_length);
    }
    d.tendon_velocity = p.tendon_slack_length * d.norm_tendon_velocity;
    d.fiber_velocity_along_tendon = path_lengthening_speed - d.tendon_velocity;
    d.fiber_velocity = d.fiber_velocity_along_tendon * d.cos_pennation;
    d.norm_fiber_velocity = d.fiber_velocity / vmax;
    d.force_velocity_multiplier = DeGrooteFregly2016Curves::ForceVelocity(d.norm_fiber_velocity);
  }
  d.pennation_angular_velocity =
      -d.fiber_velocity / d.fiber_length * (m.fiber_width() / d.fiber_length_along_tendon);

  // Forces.
  d.activation = activation;
  d.active_fiber_force =
      fiso * (activation * d.active_force_length_multiplier * d.force_velocity_multiplier);
  d.passive_elastic_fiber_force = fiso * d.passive_force_length_multiplier;
  d.passive_damping_fiber_force = fiso * p.fiber_damping * d.norm_fiber_velocity;
  d.passive_fiber_force = d.passive_elastic_fiber_force + d.passive_damping_fiber_force;
  d.fiber_force = d.active_fiber_force + d.passive_fiber_force;
  d.fiber_force_along_tendon = d.fiber_force * d.cos_pennation;
  d.norm_tendon_force = rigid ? d.fiber_force_along_tendon / fiso : norm_tendon_force;
  d.tendon_force = fiso * d.norm_tendon_force;
  d.fiber_stiffness = fiso / lopt *
                      (activation * c.ActiveForceLengthDerivative(d.norm_fiber_length) *
                           d.force_velocity_multiplier +
                       c.PassiveForceLengthDerivative(d.norm_fiber_length));
  const double dphi_dlce = (-m.fiber_width() / (d.fiber_length * d.fiber_length)) /
                           std::sqrt(1.0 - d.sin_pennation * d.sin_pennation);
  const double dfmat_dlce =
      d.fiber_stiffness * d.cos_pennation - d.fiber_force * d.sin_pennation * dphi_dlce;
  d.fiber_stiffness_along_tendon =
      dfmat_dlce / (d.cos_pennation - d.fiber_length * d.sin_pennation * dphi_dlce);
  d.tendon_stiffness =
      rigid ? std::numeric_limits<double>::infinity()
            : fiso / p.tendon_slack_length * c.TendonForceLengthDerivative(d.norm_tendon_length);
  return d;
}

double CalcDeGrooteFregly2016EquilibriumResidual(const DeGrooteFregly2016Muscle& m,
                                                 double activation, double norm_tendon_force,
                                                 double norm_tendon_force_derivative,
                                                 double path_length,
                                                 double path_lengthening_speed) {
  const DeGrooteFregly2016Dynamics d =
      CalcDeGrooteFregly2016Dynamics(m, activation, norm_tendon_force, path_length,
                                     path_lengthening_speed, norm_tendon_force_derivative);
  return d.norm_tendon_force - d.fiber_force_along_tendon / m.parameters().max_isometric_force;
}

double SolveDeGrooteFregly2016Equilibrium(const DeGrooteFregly2016Muscle& m, double activation,
                                          double path_length, double path_lengthening_speed) {
  if (m.parameters().ignore_tendon_compliance) return 0.0;
  auto residual = [&](double norm_tendon_force) {
    return CalcDeGrooteFregly2016EquilibriumResidual(m, activation, norm_tendon_force, 0.0,
                                                     path_length, path_lengthening_speed);
  };
  double left = 0.0, right = 5.0;
  double residual_left = residual(left);
  if (residual_left * residual(right) >= 0.0) {
    char text[200];
    std::snprintf(text, sizeof(text),
                  "no muscle-tendon equilibrium for a normalized tendon force in [0, 5] "
                  "(activation %g, path length %g m)",
                  activation, path_length);
    Fail(m, text);
  }
  double midpoint = left;
  for (int iteration = 0; iteration < 100 && right - left > 1e-10; ++iteration) {
    midpoint = 0.5 * (left + right);
    if (residual(midpoint) * residual_left < 0.0) {
      right = midpoint;
    } else {
      left = midpoint;
      residual_left = residual(left);
    }
  }
  return midpoint;
}

double CalcDeGrooteFregly2016ActivationDerivative(const DeGrooteFregly2016Muscle& m,
                                                  double activation, double excitation) {
  const DeGrooteFregly2016Parameters& p = m.parameters();
  const double factor = 0.5 + 1.5 * activation;
  const double rise = 1.0 / (p.activation_time_constant * factor);
  const double fall = factor / p.deactivation_time_constant;
  const double f = 0.5 * std::tanh(p.activation_dynamics_smoothing * (excitation - activation));
  return (rise * (f + 0.5) + fall * (0.5 - f)) * (excitation - activation);
}

}  // namespace sinew::muscles

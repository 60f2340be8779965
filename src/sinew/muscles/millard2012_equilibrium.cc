// The steps, their order and their tolerances follow OpenSim's Millard2012EquilibriumMuscle, so
// that an equilibrium lands on the same iterate as OpenSim's.
#include <sinew/common/error.h>
#include <sinew/muscles/millard2012_equilibrium.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace sinew::muscles {

namespace {

const double kSignificantReal = std::pow(std::numeric_limits<double>::epsilon(), 0.875);
const double kSqrtEps = std::sqrt(std::numeric_limits<double>::epsilon());

[[noreturn]] void Fail(const Millard2012Muscle& m, const std::string& what) {
  throw Error(m.parameters().name + ": " + what);
}

// Refuses inputs no muscle state can come from (NaN or infinite values, a path of length <= 0).
void CheckInputs(const Millard2012Muscle& m, double activation, double path_length,
                 double path_lengthening_speed) {
  if (!std::isfinite(activation) || !std::isfinite(path_length) || !(path_length > 0.0) ||
      !std::isfinite(path_lengthening_speed)) {
    char text[200];
    std::snprintf(text, sizeof(text),
                  "activation %g, path length %g m and lengthening speed %g m/s must be finite "
                  "(and the length positive)",
                  activation, path_length, path_lengthening_speed);
    Fail(m, text);
  }
}

// Fiso (a fal fv + fpe + beta v~): the fiber force of the damped Hill model.
double FiberForce(double fiso, double a, double fal, double fv, double fpe, double dlceN,
                  double beta) {
  return fiso * (a * fal * fv) + (fiso * fpe + fiso * beta * dlceN);
}

// dFm/dlce at fixed velocity.
double FiberStiffness(double fiso, double a, double fv, double dfpe_dlceN, double dfal_dlceN,
                      double lopt) {
  return fiso * (a * (dfal_dlceN / lopt) * fv + dfpe_dlceN / lopt);
}

// d(Fm cos phi)/d(lce) and d(Fm cos phi)/d(lce cos phi).
double DFiberForceAlongTendonDFiberLength(const FixedWidthPennation& pen, double fm, double dfm,
                                          double lce, double sin_phi, double cos_phi) {
  return dfm * cos_phi - fm * sin_phi * pen.DPennationAngleDFiberLength(lce);
}
double DFiberForceAlongTendonDLengthAlongTendon(const FixedWidthPennation& pen, double dfmat_dlce,
                                                double lce, double sin_phi, double cos_phi) {
  return dfmat_dlce / (cos_phi - lce * sin_phi * pen.DPennationAngleDFiberLength(lce));
}

// The normalized fiber velocity at which the damped fiber's force along the tendon equals the
// tendon's (Newton's method from the undamped model's inverse, as OpenSim solves it).
struct DampedVelocity {
  double norm_velocity;
  double force_velocity_multiplier;
  bool converged;
};
DampedVelocity SolveDampedNormFiberVelocity(const Millard2012Muscle& m, double fiso, double a,
                                            double fal, double fpe, double fse, double beta,
                                            double cos_phi) {
  const double tolerance = std::max(1.0e-10 * fiso, kSignificantReal * 100);
  double fv = (fse / std::max(cos_phi, 0.01) - fpe) / (std::max(a, 0.01) * std::max(fal, 0.01));
  double dlceN = std::clamp(m.force_velocity_inverse().Value(fv), -1.0, 1.0);
  double err = 1.0e10;
  for (int iteration = 0; std::abs(err) > tolerance && iteration < 20; ++iteration) {
    const SmoothSegmentedCurve::ValueAndSlope fv_eval =
        m.force_velocity().ValueAndDerivative(dlceN);
    fv = fv_eval.value;
    err = FiberForce(fiso, a, fal, fv, fpe, dlceN, beta) * cos_phi - fse * fiso;
    // beta > 0 and fv' >= 0 keep the slope positive (OpenSim perturbs randomly if it is not).
    const double derr = fiso * (a * fal * fv_eval.slope + beta) * cos_phi;
    if (std::abs(err) > tolerance && std::abs(derr) > kSignificantReal) dlceN -= err / derr;
  }
  const bool converged = std::abs(err) <= tolerance;
  return {converged ? dlceN : -1.0, fv, converged};
}

// The lengths and force-length multipliers for a fiber length (already clamped), and the
// multipliers' slopes d(fal)/d(l~), d(fpe)/d(l~).
struct ForceLengthSlopes {
  double active, passive;
};
ForceLengthSlopes CalcLengths(const Millard2012Muscle& m, double lce, double path_length,
                              Millard2012Dynamics* d) {
  const Millard2012Parameters& p = m.parameters();
  d->fiber_length = lce;
  d->norm_fiber_length = lce / p.optimal_fiber_length;
  d->pennation_angle = m.pennation().PennationAngle(lce);
  d->cos_pennation = std::cos(d->pennation_angle);
  d->sin_pennation = std::sin(d->pennation_angle);
  d->fiber_length_along_tendon = lce * d->cos_pennation;
  d->tendon_length = path_length - lce * d->cos_pennation;
  // (A rigid tendon of slack length 0 is at its slack length.)
  d->norm_tendon_length =
      p.tendon_slack_length > 0.0 ? d->tendon_length / p.tendon_slack_length : 1.0;
  const SmoothSegmentedCurve::ValueAndSlope fal =
      m.active_force_length().ValueAndDerivative(d->norm_fiber_length);
  const SmoothSegmentedCurve::ValueAndSlope fpe =
      m.fiber_force_length().ValueAndDerivative(d->norm_fiber_length);
  d->active_force_length_multiplier = fal.value;
  d->passive_force_length_multiplier = fpe.value;
  return {fal.slope, fpe.slope};
}

}  // namespace

Millard2012Dynamics CalcMillard2012Dynamics(const Millard2012Muscle& m, double activation,
                                            double fiber_length, double path_length,
                                            double path_lengthening_speed) {
  const Millard2012Parameters& p = m.parameters();
  const double fiso = p.max_isometric_force, lopt = p.optimal_fiber_length;
  const double vmax = p.max_contraction_velocity, beta = p.fiber_damping;
  const bool rigid = p.ignore_tendon_compliance;
  CheckInputs(m, activation, path_length, path_lengthening_speed);
  if (!rigid && !std::isfinite(fiber_length)) Fail(m, "the fiber length is not finite");
  Millard2012Dynamics d;
  const double lce = m.ClampFiberLength(
      rigid ? m.pennation().FiberLength(path_length, p.tendon_slack_length) : fiber_length);
  const ForceLengthSlopes slopes = CalcLengths(m, lce, path_length, &d);
  const double a = m.ClampActivation(activation);
  d.activation = a;

  // Velocities.
  double fse = std::numeric_limits<double>::quiet_NaN();
  double tendon_stiffness = std::numeric_limits<double>::infinity();
  if (!rigid) {
    const SmoothSegmentedCurve::ValueAndSlope fse_eval =
        m.tendon_force_length().ValueAndDerivative(d.norm_tendon_length);
    fse = fse_eval.value;
    tendon_stiffness = fse_eval.slope * fiso / p.tendon_slack_length;
  }
  double dlce = 0.0, dlceN = 0.0, fv = 1.0;
  if (rigid) {
    if (!(d.tendon_length < p.tendon_slack_length - kSignificantReal)) {
      dlce = path_lengthening_speed * d.cos_pennation;
      dlceN = dlce / (lopt * vmax);
      fv = m.force_velocity().Value(dlceN);
    }
  } else if (!m.uses_fiber_damping()) {
    if (!(d.cos_pennation > kSignificantReal)) Fail(m, "pennation angle is 90 degrees");
    if (!(a > kSignificantReal)) Fail(m, "activation is 0 in the undamped model");
    if (!(d.active_force_length_multiplier > kSignificantReal)) {
      Fail(m, "the active-force-length multiplier is 0 in the undamped model");
    }
    fv = (fse / d.cos_pennation - d.passive_force_length_multiplier) /
         (a * d.active_force_length_multiplier);
    dlceN = m.force_velocity_inverse().Value(fv);
    dlce = dlceN * vmax * lopt;
  } else {
    const DampedVelocity v =
        SolveDampedNormFiberVelocity(m, fiso, a, d.active_force_length_multiplier,
                                     d.passive_force_length_multiplier, fse, beta, d.cos_pennation);
    if (!v.converged) Fail(m, "the fiber velocity Newton iteration did not converge");
    dlceN = v.norm_velocity;
    dlce = dlceN * lopt * vmax;
    fv = v.force_velocity_multiplier;
  }
  double dphidt = m.pennation().PennationAngularVelocity(std::tan(d.pennation_angle), lce, dlce);
  double dlceAT = dlce * d.cos_pennation - lce * d.sin_pennation * dphidt;
  double dtl =
      rigid ? 0.0
            : path_lengthening_speed - dlce * d.cos_pennation + lce * d.sin_pennation * dphidt;
  const double min_length = m.minimum_fiber_length();
  d.fiber_state_clamped = (lce <= min_length && dlce <= 0.0) || lce < min_length;
  if (d.fiber_state_clamped) {
    dlce = dlceN = dlceAT = dphidt = 0.0;
    dtl = path_lengthening_speed;
    fv = 1.0;
  }
  d.fiber_velocity = dlce;
  d.norm_fiber_velocity = dlceN;
  d.fiber_velocity_along_tendon = dlceAT;
  d.pennation_angular_velocity = dphidt;
  d.tendon_velocity = dtl;
  d.force_velocity_multiplier = fv;

  // Forces.
  if (!d.fiber_state_clamped) {
    double active = fiso * (a * d.active_force_length_multiplier * fv);
    double elastic = fiso * d.passive_force_length_multiplier;
    double damping = fiso * beta * dlceN;
    double fm = active + (elastic + damping);
    if (rigid && fm < 0.0) {  // a rigid tendon cannot push: the damping takes the difference
      fm = 0.0;
      damping = -active - elastic;
    }
    d.active_fiber_force = active;
    d.passive_elastic_fiber_force = elastic;
    d.passive_damping_fiber_force = damping;
    d.passive_fiber_force = elastic + damping;
    d.fiber_force = fm;
    d.fiber_force_along_tendon = fm * d.cos_pennation;
    d.fiber_stiffness = FiberStiffness(fiso, a, fv, slopes.passive, slopes.active, lopt);
    const double dfmat_dlce = DFiberForceAlongTendonDFiberLength(
        m.pennation(), fm, d.fiber_stiffness, lce, d.sin_pennation, d.cos_pennation);
    d.fiber_stiffness_along_tendon = DFiberForceAlongTendonDLengthAlongTendon(
        m.pennation(), dfmat_dlce, lce, d.sin_pennation, d.cos_pennation);
    d.tendon_stiffness = tendon_stiffness;
  }
  d.norm_tendon_force = rigid ? d.fiber_force_along_tendon / fiso : fse;
  d.tendon_force = d.norm_tendon_force * fiso;
  return d;
}

Millard2012PotentialEnergy CalcMillard2012PotentialEnergy(const Millard2012Muscle& m,
                                                          const Millard2012Dynamics& d) {
  const Millard2012Parameters& p = m.parameters();
  Millard2012PotentialEnergy energy;
  energy.fiber = p.optimal_fiber_length * p.max_isometric_force *
                 m.fiber_force_length().Integral(d.norm_fiber_length);
  if (!p.ignore_tendon_compliance) {
    energy.tendon = p.tendon_slack_length * p.max_isometric_force *
                    m.tendon_force_length().Integral(d.norm_tendon_length);
  }
  return energy;
}

double CalcMillard2012ActivationDerivative(const Millard2012Muscle& m, double activation,
                                           double excitation) {
  const Millard2012Parameters& p = m.parameters();
  const double a = m.ClampActivation(activation);
  const double tau = excitation > a ? p.activation_time_constant * (0.5 + 1.5 * a)
                                    : p.deactivation_time_constant / (0.5 + 1.5 * a);
  return (excitation - a) / tau;
}

Millard2012Equilibrium SolveMillard2012Equilibrium(const Millard2012Muscle& m, double activation,
                                                   double path_length,
                                                   double path_lengthening_speed) {
  const Millard2012Parameters& p = m.parameters();
  Millard2012Equilibrium result;
  CheckInputs(m, activation, path_length, path_lengthening_speed);
  if (p.ignore_tendon_compliance) {
    const Millard2012Dynamics d = CalcMillard2012Dynamics(m, activation, 0.0, path_length, 0.0);
    result.fiber_length = d.fiber_length;
    result.tendon_force = d.tendon_force;
    return result;
  }
  const FixedWidthPennation& pen = m.pennation();
  const double ma = m.ClampActivation(activation);
  const double ml = path_length, dml = path_lengthening_speed;
  const bool static_solution = !(std::abs(dml) >= kSignificantReal);
  const double tsl = p.tendon_slack_length, ofl = p.optimal_fiber_length;
  const double fiso = p.max_isometric_force, vmax = p.max_contraction_velocity;
  const double beta = p.fiber_damping;
  const double tolerance = std::max(1e-8 * fiso, kSignificantReal * 10);
  constexpr int kMaxIterations = 200;

  double lce = m.ClampFiberLength(pen.FiberLength(ml, tsl * 1.01));
  double phi = 0, cos_phi = 1, sin_phi = 0, tl = 0, lceN = 0, tlN = 0;
  double fal = 0, fpe = 0, fse = 0, fv = 1.0, dlceN = 0;
  double fm = 0, ferr = 0;
  double dfmat_dlce = 0, dfmat_dlceat = 0, dft_dtl = 0, dft_dlce = 0;
  auto positions = [&] {
    phi = pen.PennationAngle(lce);
    cos_phi = std::cos(phi);
    sin_phi = std::sin(phi);
    tl = ml - lce * cos_phi;
    lceN = lce / ofl;
    tlN = tl / tsl;
  };
  auto multipliers = [&] {
    fal = m.active_force_length().Value(lceN);
    fpe = m.fiber_force_length().Value(lceN);
    fse = m.tendon_force_length().Value(tlN);
  };
  auto error = [&] {
    fm = FiberForce(fiso, ma, fal, fv, fpe, dlceN, beta);
    ferr = fm * cos_phi - fse * fiso;
  };
  auto partials = [&] {
    const double dfm = FiberStiffness(fiso, ma, fv, m.fiber_force_length().Derivative(lceN, 1),
                                      m.active_force_length().Derivative(lceN, 1), ofl);
    dfmat_dlce = DFiberForceAlongTendonDFiberLength(pen, fm, dfm, lce, sin_phi, cos_phi);
    dfmat_dlceat = DFiberForceAlongTendonDLengthAlongTendon(pen, dfmat_dlce, lce, sin_phi, cos_phi);
    dft_dtl = m.tendon_force_length().Derivative(tlN, 1) * fiso / tsl;
    // d(tl)/d(lce) = lce sin(phi) dphi/dlce - cos(phi).
    dft_dlce = dft_dtl * (lce * sin_phi * pen.DPennationAngleDFiberLength(lce) - cos_phi);
  };
  // With a path speed, the tendon takes the share of it that keeps fiber and tendon forces equal
  // to first order (their stiffnesses in series); the fiber the rest.
  auto velocities = [&] {
    if (static_solution) return;
    const double dtl = std::abs(dfmat_dlceat + dft_dtl) > kSignificantReal && tlN > 1.0
                           ? dfmat_dlceat / (dfmat_dlceat + dft_dtl) * dml
                           : dml;
    dlceN = (dml - dtl) * cos_phi / (vmax * ofl);
    fv = m.force_velocity().Value(dlceN);
  };

  positions();
  multipliers();
  fm = FiberForce(fiso, ma, fal, fv, fpe, dlceN, beta);
  partials();
  velocities();
  error();
  partials();
  double ferr_prev = ferr, lce_prev = lce;
  int iteration = 0;
  while (std::abs(ferr) > tolerance && iteration < kMaxIterations) {
    const double dferr_dlce = dfmat_dlce - dft_dlce;
    // Newton's step, halved until the error shrinks (the first pass always runs).
    double h = 1.0;
    while (std::abs(ferr) >= std::abs(ferr_prev)) {
      const double delta = -h * ferr_prev / dferr_dlce;
      if (std::abs(delta) > kSignificantReal) {
        lce = lce_prev + delta;
      } else {
        lce = lce_prev - (delta > 0 ? 1.0 : delta < 0 ? -1.0 : 0.0) * kSqrtEps;
        h = 0.0;
      }
      lce = std::max(lce, m.minimum_fiber_length());
      positions();
      multipliers();
      error();
      if (h <= kSqrtEps) break;
      h *= 0.5;
    }
    ferr_prev = ferr;
    lce_prev = lce;
    partials();
    velocities();
    ++iteration;
  }
  result.iterations = iteration;
  result.solution_error = ferr;
  if (std::abs(ferr) < tolerance) {
    result.fiber_length = m.ClampFiberLength(lce);
    result.tendon_force = fse * fiso;
    return result;
  }
  if (lce <= m.minimum_fiber_length()) {
    result.status = Millard2012Equilibrium::Status::kFiberAtLowerBound;
    lce = m.minimum_fiber_length();
    const double tendon_length = ml - lce * std::cos(pen.PennationAngle(lce));
    result.fiber_length = lce;
    result.tendon_force = m.tendon_force_length().Value(tendon_length / tsl) * fiso;
    return result;
  }
  char text[300];
  std::snprintf(text, sizeof(text),
                "failed to compute muscle equilibrium: solution error %g N exceeds the tolerance "
                "of %g N after %d Newton iterations (activation %g, path length %g m, fiber "
                "length %g m)",
                std::abs(ferr), tolerance, kMaxIterations, ma, ml, lce);
  Fail(m, text);
}

}  // namespace sinew::muscles

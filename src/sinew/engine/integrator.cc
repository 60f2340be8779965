#include <sinew/common/error.h>
#include <sinew/common/text.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/cvode_integrator.h>
#include <sinew/engine/dynamics.h>
#include <sinew/engine/fixed_step_integrator.h>
#include <sinew/engine/force_jacobian.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/pose.h>
#include <sinew/engine/projection.h>
#include <sinew/engine/state_vector.h>
#include <sinew/engine/tree_displacement.h>

#include <Eigen/LU>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace sinew::engine {

Integrator::Integrator(const System& system, const IntegratorSettings& settings)
    : system_(system), settings_(settings), data_(system), kkt_(data_.kkt) {
  if (!(settings.accuracy > 0.0)) throw Error("integrator: accuracy must be > 0");
  if (settings.step < 0.0) throw Error("integrator: step must be >= 0");
}

void Integrator::StepTo(State& state, double t_final) {
  CheckState(system_, state);
  if (!(t_final >= state.t)) throw Error("integrator: cannot step backwards in time");
  system_.UpdateDiscreteData(state, /*only_missing=*/true);
  while (state.t < t_final) {
    TakeStep(state, t_final);
    system_.UpdateDiscreteData(state);
  }
  ApplyController(state);
}

void Integrator::Advance(State& state, double t_limit) {
  CheckState(system_, state);
  if (!(t_limit > state.t)) throw Error("integrator: Advance needs a time after the state's");
  system_.UpdateDiscreteData(state, /*only_missing=*/true);
  TakeStep(state, t_limit);
  system_.UpdateDiscreteData(state);
  ApplyController(state);
}

void Integrator::Interpolate(double, State&) {
  throw Error("integrator: this scheme has no dense output; step to each time instead");
}

void Integrator::ApplyController(State& state) const {
  if (controller_) controller_->CalcInputs(system_, state, state.inputs);
}

void Integrator::ApplyInputs(State& state) {
  ApplyController(state);
  ++stats_.evaluations;
}

const Accelerations& Integrator::Evaluate(State& state, Eigen::Ref<VecX> zdot) {
  ApplyInputs(state);
  return CalcAccelerationsReusingFactorization(system_, state, external_, data_,
                                               zdot.size() > 0 ? &zdot : nullptr);
}

void Integrator::EvaluateForces(State& state, Eigen::Ref<VecX> zdot, Eigen::Ref<VecX> force_rhs) {
  ApplyInputs(state);
  CalcForceRhsReusingFactorization(system_, state, external_, data_, force_rhs,
                                   zdot.size() > 0 ? &zdot : nullptr);
}

double Integrator::ConstraintTolerance() const {
  return settings_.constraint_tolerance > 0.0 ? settings_.constraint_tolerance
                                              : std::min(1e-3 * settings_.accuracy, 1e-10);
}

namespace {

// Dormand-Prince 5(4) with projection after every accepted step.
class RungeKutta45 final : public Integrator {
 public:
  RungeKutta45(const System& system, const IntegratorSettings& settings)
      : Integrator(system, settings), vector_(system, kkt_) {}

  bool HasDenseOutput() const override { return true; }
  void Interpolate(double t, State& out) override;

 protected:
  void TakeStep(State& state, double t_final) override {
    if (h_ <= 0.0) h_ = settings_.step > 0.0 ? std::min(settings_.step, 1e-3) : 1e-3;
    // The first stage, the derivative at the step's own state, serves every trial of the step.
    y0_ = vector_.Pack(state);
    if (!FirstStageFromLastStep(state)) EvalFirstStage(state);
    step_from_ = state.t;
    if (CrossJustAhead(state, t_final)) {
      // The step that failed across it says how long a step may be; the short one that ended
      // just before it says nothing.
      h_ = std::max(h_, step_across_);
      y0_ = vector_.Pack(state);
      EvalFirstStage(state);
    }
    // That length holds for the crossing just ahead only (a coordinate that turned back short of
    // it would hand it to an unrelated later crossing).
    step_across_ = 0.0;
    for (;;) {
      const double remaining = t_final - state.t;
      double h = std::min(h_, remaining);
      if (settings_.step > 0.0) h = std::min(h, settings_.step);
      // Avoid a tiny last step: split the remainder evenly instead.
      if (h < remaining && remaining < 1.5 * h) h = 0.5 * remaining;
      const bool lands = h >= remaining;
      if (TryStep(state, lands ? remaining : h, lands ? t_final : state.t + h)) {
        ++stats_.steps;
        return;
      }
      ++stats_.rejected;
      if (h_ < settings_.min_step) {
        throw Error("integrator 'rk45': the step size fell below " +
                    FormatNumber(settings_.min_step) + " s at t = " + FormatNumber(state.t) +
                    " s (" + std::to_string(stats_.rejected) + " steps rejected, " +
                    std::to_string(stats_.projection_failures) +
                    " of them because the position projection did not converge)" +
                    (last_failure_.empty() ? "" : "; last failed trial: " + last_failure_) +
                    ": the motion may be singular there; try a looser accuracy or check the "
                    "model");
      }
    }
  }

 private:
  // k_[0], the derivative at `state` (packed in y0_).
  void EvalFirstStage(const State& state) {
    State scratch = state;
    Eval(y0_, state.t, scratch, k_[0]);
  }

  // ydot at (y, t) into `ydot`.
  void Eval(const VecX& y, double t, State& scratch, VecX& ydot) {
    vector_.Unpack(y, t, scratch);
    zdot_.resize(vector_.num_state_variables());
    const Accelerations& acc = Evaluate(scratch, zdot_);
    ydot.resize(vector_.size());
    vector_.Derivative(y, scratch, acc.vdot, zdot_, ydot);
  }

  // Eval at a stage of a trial step. False when the stage's state is not finite or a force's
  // loads or derivatives are not (a trial step far too long for a stiff muscle): the step fails
  // and is retried shorter, as for a large error estimate.
  bool TryEval(const VecX& y, double t, State& scratch, VecX& ydot) {
    if (!y.allFinite()) {
      last_failure_ = "a trial state was not finite at t = " + FormatNumber(t) + " s";
      return false;
    }
    try {
      Eval(y, t, scratch, ydot);
    } catch (const NonFiniteForceError& e) {
      last_failure_ = e.what();
      return false;
    }
    return true;
  }

  // One attempt; on success `state` advances and h_ is updated for the next step.
  bool TryStep(State& state, double h, double t_new) {
    static constexpr double c[7] = {0, 1.0 / 5, 3.0 / 10, 4.0 / 5, 8.0 / 9, 1, 1};
    static constexpr double a[7][6] = {
        {0, 0, 0, 0, 0, 0},
        {1.0 / 5, 0, 0, 0, 0, 0},
        {3.0 / 40, 9.0 / 40, 0, 0, 0, 0},
        {44.0 / 45, -56.0 / 15, 32.0 / 9, 0, 0, 0},
        {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729, 0, 0},
        {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656, 0},
        {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84}};
    // Error coefficients: fifth-order minus fourth-order weights.
    static constexpr double e[7] = {71.0 / 57600,      0,          -71.0 / 16695, 71.0 / 1920,
                                    -17253.0 / 339200, 22.0 / 525, -1.0 / 40};
    State scratch = state;
    const VecX& y0 = y0_;  // packed by TakeStep, with k[0]
    VecX* k = k_;
    VecX y;
    for (int s = 1; s < 7; ++s) {
      y = y0;
      for (int j = 0; j < s; ++j) {
        if (a[s][j] != 0.0) y += (h * a[s][j]) * k[j];
      }
      if (!TryEval(y, s == 6 ? t_new : state.t + c[s] * h, scratch, k[s])) {
        h_ = 0.2 * h;
        just_rejected_ = true;
        return false;
      }
    }
    // y holds the fifth-order solution (the last stage is evaluated at it).
    VecX err = VecX::Zero(y0.size());
    for (int s = 0; s < 7; ++s) err += (h * e[s]) * k[s];
    double norm = 0.0;
    for (int i = 0; i < err.size(); ++i) {
      const double scale = std::max({1.0, std::abs(y0[i]), std::abs(y[i])});
      norm = std::max(norm, std::abs(err[i]) / scale);
    }
    norm /= settings_.accuracy;
    if (!std::isfinite(norm)) norm = 1e10;
    // A failing step across a breakpoint (System::breakpoints: the accelerations or their rate
    // jump there, so the error is that of the jump) is retried to end just short of the first
    // one it crosses, instead of shorter by the error's rule; the next step starts by crossing it
    // (CrossJustAhead). The trial's end state, unpacked once: for this test and, when accepted,
    // the step.
    const bool unpacked = !system_.breakpoints().empty();
    if (unpacked) {
      trial_ = state;
      vector_.Unpack(y, t_new, trial_);
      const double to_breakpoint = norm > 1.0 ? FractionToBreakpoint(state, trial_) : 1.0;
      if (to_breakpoint < 1.0) {
        h_ = h * to_breakpoint * (1.0 - 1e-8);
        step_across_ = std::max(step_across_, h);
        return false;
      }
    }
    const double factor = norm == 0.0 ? 5.0 : std::clamp(0.9 * std::pow(norm, -0.2), 0.2, 5.0);
    if (norm > 1.0) {
      h_ = h * std::min(factor, 0.9);
      just_rejected_ = true;
      return false;
    }
    // Dense output (Hairer's fourth-order continuous extension of Dormand-Prince), kept for
    // Interpolate: y(t0 + theta h) = y0 + theta (d1 + (1 - theta) (d2 + theta (d3 +
    // (1 - theta) d4))), from the step's stages and the unprojected fifth-order solution.
    static constexpr double d[7] = {-12715105075.0 / 11282082432.0,  0,
                                    87487479700.0 / 32700410799.0,   -10690763975.0 / 1880347072.0,
                                    701980252875.0 / 199316789632.0, -1453857185.0 / 822651844.0,
                                    69997945.0 / 29380423.0};
    dense_.t0 = state.t;
    dense_.h = h;
    dense_.y0 = y0;
    dense_.d1 = y - y0;
    dense_.d2 = h * k[0] - dense_.d1;
    dense_.d3 = dense_.d1 - h * k[6] - dense_.d2;
    dense_.d4 = VecX::Zero(y0.size());
    for (int s = 0; s < 7; ++s) {
      if (d[s] != 0.0) dense_.d4 += (h * d[s]) * k[s];
    }
    dense_.start = state;
    State next = unpacked ? std::move(trial_) : state;
    if (!unpacked) vector_.Unpack(y, t_new, next);
    if (!ProjectPositions(system_, next, ConstraintTolerance(), kkt_, 10,
                          &stats_.projection_factorizations)) {
      ++stats_.projection_failures;
      h_ = 0.5 * h;
      return false;
    }
    ProjectVelocities(system_, next, kkt_);
    UpdateDirectCoordinates(system_, next);
    state = std::move(next);
    KeepLastStage(state);
    // No growth right after a rejection (Hairer's rule: avoids reject/accept cycles). A step
    // shortened to land on t_final says little about the next one.
    const double growth = just_rejected_ ? std::min(factor, 1.0) : factor;
    just_rejected_ = false;
    h_ = h < h_ ? std::max(h_, h * growth) : h * growth;
    if (settings_.step > 0.0) h_ = std::min(h_, settings_.step);
    return true;
  }

  // Dormand-Prince's last stage is the derivative at the step's end ("first same as last"),
  // before the projection: the next step starts from it instead of evaluating again (a seventh
  // of the evaluations) when it starts where this one ended (nothing changed the state, its
  // inputs, the external loads or the controller in between) and no element keeps discrete
  // data (updated between steps). Only the accelerations and the state variables' derivatives
  // are taken over; the positions' rates are recomputed from the projected velocities. The
  // projection moved the state by the order of the local error, so the accelerations taken
  // over differ from those at the projected state by that much times their sensitivity; they
  // enter the next step multiplied by h, a term one order above the method's local error.
  void KeepLastStage(const State& state) {
    last_.valid = !system_.HasDiscreteData();
    if (!last_.valid) return;
    last_.y.resize(vector_.size());
    vector_.PackInto(state, last_.y);
    last_.t = state.t;
    last_.inputs = state.inputs;
    last_.setup_changes = setup_changes_;
  }

  // k_[0] from the last step's last stage, when KeepLastStage's conditions hold for `state`
  // (packed in y0_). True when it did.
  bool FirstStageFromLastStep(const State& state) {
    const bool same = last_.valid && last_.t == state.t && last_.setup_changes == setup_changes_ &&
                      last_.y.size() == y0_.size() && last_.y == y0_ &&
                      (controller_ || last_.inputs == state.inputs);
    last_.valid = false;
    if (!same) return false;
    const int nv = vector_.num_velocities(), nz = vector_.num_state_variables();
    const int np = vector_.size() - nv - nz;
    k_[0].resize(vector_.size());
    vector_.Derivative(y0_, state, k_[6].segment(np, nv), k_[6].tail(nz), k_[0]);
    ++stats_.first_stages_reused;
    return true;
  }

  // The fraction of the trial step from `state` to `trial` at which a free coordinate first
  // reaches a breakpoint it crosses, or 1 when it crosses none. The coordinate's course is taken
  // as the cubic with its values and rates at the two ends (its error, of the order of the
  // step's fourth power, leaves the step ending near the breakpoint; the next trials close in).
  // A crossing too near the step's start to end short of (a step of 1e-9 s) is left to the
  // error control.
  double FractionToBreakpoint(const State& state, const State& trial) const {
    double fraction = 1.0;
    const double h = trial.t - state.t;
    for (const auto& [coordinate, value] : system_.breakpoints()) {
      const double g0 = state.q[coordinate] - value, g1 = trial.q[coordinate] - value;
      if (g0 * g1 < 0.0) {
        fraction =
            std::min(fraction, CubicRoot(g0, h * state.u[coordinate], g1, h * trial.u[coordinate]));
      }
    }
    return fraction * h > 1e-9 ? fraction : 1.0;
  }

  // Where in (0, 1) the cubic with g(0) = g0, g(1) = g1 (of opposite signs), g'(0) = d0 and
  // g'(1) = d1 (Hermite's) is zero: Newton's method from the chord's zero, falling back to
  // bisection when a step leaves the bracket.
  static double CubicRoot(double g0, double d0, double g1, double d1) {
    double lo = 0.0, hi = 1.0, s = g0 / (g0 - g1);
    for (int i = 0; i < 20; ++i) {
      const double s2 = s * s, s3 = s2 * s;
      const double g = (2 * s3 - 3 * s2 + 1) * g0 + (s3 - 2 * s2 + s) * d0 +
                       (3 * s2 - 2 * s3) * g1 + (s3 - s2) * d1;
      const double dg =
          6 * (s2 - s) * (g0 - g1) + (3 * s2 - 4 * s + 1) * d0 + (3 * s2 - 2 * s) * d1;
      ((g < 0.0) == (g0 < 0.0) ? lo : hi) = s;
      double next = s - g / dg;
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      if (std::abs(next - s) <= 1e-14) return next;
      s = next;
    }
    return s;
  }

  // A step ended just short of a breakpoint: the coordinate, moving towards it, reaches it
  // within 1e-7 of the next step (or 1e-10 s), before t_final. Then `state` crosses it by one
  // explicit Euler step of that length (its error, of the order of the step squared, is far
  // below the accuracy), so that the next step's stages all lie past it. True when it did.
  bool CrossJustAhead(State& state, double t_final) {
    const auto& breakpoints = system_.breakpoints();
    double step = 0.0;
    for (const auto& [coordinate, value] : breakpoints) {
      const double gap = value - state.q[coordinate], u = state.u[coordinate];
      if (u == 0.0 || gap * u <= 0.0) continue;
      const double dt = gap / u;
      if (dt <= std::max(1e-7 * h_, 1e-10)) step = std::max(step, dt * (1.0 + 1e-6) + 1e-15);
    }
    if (step == 0.0 || !(state.t + 2.0 * step < t_final)) return false;
    const VecX q0 = state.q;
    y0_ += step * k_[0];
    vector_.Unpack(y0_, state.t + step, state);
    for (const auto& [coordinate, value] : breakpoints) {
      if ((q0[coordinate] - value) * (state.q[coordinate] - value) < 0.0) {
        ++stats_.breakpoints_crossed;
      }
    }
    return true;
  }

  // The last accepted step, for Interpolate.
  struct DenseOutput {
    double t0 = 0.0, h = 0.0;
    VecX y0, d1, d2, d3, d4;
    State start;  // the state the step started from (inputs, direct-joint angle branches)
  };

  StateVector vector_;
  DenseOutput dense_;
  VecX zdot_;
  VecX y0_;    // the step's start, packed
  VecX k_[7];  // the stages' derivatives
  double h_ = 0.0;
  bool just_rejected_ = false;
  State trial_;  // a trial step's end state, unpacked (models with breakpoints)
  struct {
    bool valid = false;
    VecX y;  // the accepted state, projected and packed
    double t = 0.0;
    VecX inputs;
    long setup_changes = 0;
  } last_;                    // the last accepted step's end, whose derivative k_[6] holds
  double step_from_ = 0.0;    // the last step's start before CrossJustAhead moved it
  double step_across_ = 0.0;  // the step's longest trial retried to end short of a breakpoint
  std::string last_failure_;  ///< why the last trial stage failed (for the step-size error)
};

void RungeKutta45::Interpolate(double t, State& out) {
  const double h = dense_.h;
  // From where the step started before crossing a breakpoint just ahead (at most 1e-7 of it
  // earlier: those times get the crossed state).
  const double from = std::min(dense_.t0, step_from_);
  if (!(h > 0.0) || !(t >= from - 1e-12 * h && t <= dense_.t0 + h * (1 + 1e-12))) {
    throw Error("integrator 'rk45': Interpolate at t = " + FormatNumber(t) +
                " s, outside the last step");
  }
  const double theta = std::clamp((t - dense_.t0) / h, 0.0, 1.0);
  const VecX y =
      dense_.y0 +
      theta *
          (dense_.d1 + (1 - theta) * (dense_.d2 + theta * (dense_.d3 + (1 - theta) * dense_.d4)));
  out = dense_.start;
  vector_.Unpack(y, t, out);
  if (!system_.constraints().empty()) {
    // The interpolant is as accurate as the steps, but not on the constraints: project it, as
    // every accepted step is.
    if (!ProjectPositions(system_, out, ConstraintTolerance(), kkt_, 10,
                          &stats_.projection_factorizations)) {
      throw Error("integrator 'rk45': the interpolated state at t = " + FormatNumber(t) +
                  " s could not be projected onto the constraints");
    }
    ProjectVelocities(system_, out, kkt_);
    UpdateDirectCoordinates(system_, out);
  }
  ApplyController(out);
}

// Fixed-step semi-implicit Euler on the velocity-level KKT system, with projection.
class SemiImplicitEuler final : public FixedStepIntegrator {
 public:
  SemiImplicitEuler(const System& system, const IntegratorSettings& settings)
      : FixedStepIntegrator(system, settings, "euler") {}

 private:
  void Step(State& state, double h, double t_new) override {
    SolveFreeVelocities(state, h, t_new);
    FinishStep(state, h);
  }
};

// Linearized implicit Euler (fixed step): the applied loads f(x, v) are linearized about the
// step's start with K = df/dx and D = df/dv (CalcLoadJacobians: gravity analytic, each force
// element's own blocks or central differences over its support),
//   [M - h D - h^2 K   J^T] [v+ ]   [M (v + h vdot) - h D v]
//   [J                  0 ] [mu ] = [c(t + h)              ]
// then positions move with v+ and are projected. Stable for stiff springs and dampers. The
// matrix is sparse (block-diagonal M, each constraint's few columns, K and D on the bodies and
// coordinates a load couples), so it is factorized by Eigen's SparseLU (COLAMD ordering,
// partial pivoting): a dense LU of a whole skeleton's KKT matrix (about 300 rows) took most of
// the step.
class LinearizedImplicitEuler final : public FixedStepIntegrator {
 public:
  LinearizedImplicitEuler(const System& system, const IntegratorSettings& settings)
      : FixedStepIntegrator(system, settings, "implicit-euler") {}

 private:
  void Step(State& state, double h, double t_new) override {
    const int nv = kkt_.num_velocities(), nc = kkt_.num_equations();
    VecX zdot(system_.num_state_variables());
    const Accelerations& acc = Evaluate(state, zdot);
    const VecX v0 = GatherVelocities(system_, kkt_, state);
    CalcLoadJacobians(system_, kkt_, state, K_, D_);
    entries_.clear();
    kkt_.AppendTriplets(entries_);
    for (int j = 0; j < nv; ++j) {
      for (int i = 0; i < nv; ++i) {
        const double a = h * D_(i, j) + h * h * K_(i, j);
        if (a != 0.0) entries_.emplace_back(i, j, -a);
      }
    }
    A_.resize(nv + nc, nv + nc);
    A_.setFromTriplets(entries_.begin(), entries_.end());
    VecX rhs(nv + nc);
    rhs.head(nv) = kkt_.MultiplyMass(v0 + h * acc.vdot) - h * (D_ * v0);
    State later = state;
    later.t = t_new;
    SetVelocityRhs(later, rhs);
    lu_.compute(A_);
    VecX x;
    if (lu_.info() == Eigen::Success) x = lu_.solve(rhs);
    if (lu_.info() != Eigen::Success || !x.allFinite() ||
        (A_ * x - rhs).lpNorm<Eigen::Infinity>() > 1e-6 * (1.0 + rhs.lpNorm<Eigen::Infinity>())) {
      throw Error("integrator 'implicit-euler': singular step matrix at t = " +
                  std::to_string(state.t) + " s");
    }
    const VecX v1 = x.head(nv);
    ScatterVelocities(system_, kkt_, v1, later);
    ApplyTreeDisplacement(system_, kkt_, h * v1, later);
    later.z += h * zdot;  // explicit in z (the loads' z-dependence is not linearized yet)
    ProjectAfterStep(later, state.t);
    state = std::move(later);
  }

  // Kept between steps, so that their memory is reused.
  MatX K_, D_;
  std::vector<Eigen::Triplet<double>> entries_;
  Eigen::SparseMatrix<double> A_;
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu_;
};

}  // namespace

namespace {

using Maker = std::unique_ptr<Integrator> (*)(const System&, const IntegratorSettings&);

template <class Scheme>
std::unique_ptr<Integrator> Make(const System& system, const IntegratorSettings& settings) {
  return std::make_unique<Scheme>(system, settings);
}

template <CvodeLinearSolver kSolver>
std::unique_ptr<Integrator> MakeCvode(const System& system, const IntegratorSettings& settings) {
  return MakeCvodeIntegrator(system, settings, kSolver);
}

// Every scheme by name (aliases included), in the order the error message lists them.
constexpr struct {
  const char* name;
  Maker make;
} kIntegrators[] = {
    {"rk45", &Make<RungeKutta45>},
    {"dopri5", &Make<RungeKutta45>},
    {"cvode", &MakeCvode<CvodeLinearSolver::kDense>},
    {"cvode-gmres", &MakeCvode<CvodeLinearSolver::kGmres>},
    {"cvode-gmres-bd", &MakeCvode<CvodeLinearSolver::kGmresBlockPreconditioned>},
    {"euler", &Make<SemiImplicitEuler>},
    {"semi-implicit-euler", &Make<SemiImplicitEuler>},
    {"implicit-euler", &Make<LinearizedImplicitEuler>},
};

}  // namespace

std::unique_ptr<Integrator> MakeIntegrator(const std::string& name, const System& system,
                                           const IntegratorSettings& settings) {
  for (const auto& entry : kIntegrators) {
    if (name == entry.name) return entry.make(system, settings);
  }
  throw Error("unknown integrator '" + name +
              "' (known: rk45, cvode, cvode-gmres, cvode-gmres-bd, euler, implicit-euler)");
}

}  // namespace sinew::engine

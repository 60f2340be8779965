#include <sinew/common/error.h>
#include <sinew/common/text.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/fixed_step_integrator.h>
#include <sinew/engine/projection.h>
#include <sinew/engine/tree_displacement.h>

#include <limits>
#include <string>

namespace sinew::engine {

FixedStepIntegrator::FixedStepIntegrator(const System& system, const IntegratorSettings& settings,
                                         const char* name)
    : Integrator(system, settings), name_(name) {
  if (!(settings.step > 0.0)) {
    throw Error(std::string("integrator '") + name + "' needs a step > 0");
  }
}

void FixedStepIntegrator::TakeStep(State& state, double t_final) {
  const double remaining = t_final - state.t;
  const double h = remaining < 1.0001 * settings_.step ? remaining : settings_.step;
  Step(state, h, h == remaining ? t_final : state.t + h);
  ++stats_.steps;
}

void FixedStepIntegrator::SetVelocityRhs(const State& later, VecX& rhs) const {
  const int nv = kkt_.num_velocities();
  const auto& constraints = system_.constraints();
  for (size_t k = 0; k < constraints.size(); ++k) {
    constraints[k]->CalcVelocityRhs(
        system_, later, rhs.segment(nv + kkt_.EquationRow(k), constraints[k]->NumEquations()));
  }
}

void FixedStepIntegrator::ProjectAfterStep(State& later, double t_start) {
  constexpr int kIterations = 10;
  if (!TryStartFactorization(later) &&
      !ProjectPositions(system_, later, ConstraintTolerance(), kkt_, kIterations,
                        &stats_.projection_factorizations)) {
    ++stats_.projection_failures;
    const VecX phi = CalcPositionErrors(system_, later);
    throw Error(
        "integrator '" + name_ + "': position projection failed in the step from t = " +
        FormatNumber(t_start) + " s to t = " + FormatNumber(later.t) +
        " s: the largest constraint error is still " + FormatNumber(phi.lpNorm<Eigen::Infinity>()) +
        " after " + std::to_string(kIterations) + " Newton iterations (tolerance " +
        FormatNumber(ConstraintTolerance()) + "). A fixed step of " + FormatNumber(settings_.step) +
        " s is likely too large for this motion: try a smaller step, or the "
        "error-controlled integrator rk45, which shortens its steps where needed");
  }
  ProjectVelocities(system_, later, kkt_);
  UpdateDirectCoordinates(system_, later);
}

void FixedStepIntegrator::SolveFreeVelocities(State& state, double h, double t_new) {
  const int nv = kkt_.num_velocities();
  zdot_.resize(system_.num_state_variables());
  force_rhs_.resize(nv);
  EvaluateForces(state, zdot_, force_rhs_);
  v0_.resize(nv);
  GatherVelocities(system_, kkt_, state, v0_);
  // M v+ + J^T mu = M v0 + h f with f the loads less the velocity terms: the step's
  // M (v0 + h vdot) = M v0 + h f - h J^T lambda differs from it only by a term in the range of
  // J^T, which mu takes up, so the acceleration solve is not needed.
  free_rhs_.resize(nv + kkt_.num_equations());
  kkt_.MultiplyMass(v0_, mv_);
  free_rhs_.head(nv) = mv_ + h * force_rhs_;
  later_ = state;  // copies into the buffers of an earlier step's state
  later_.t = t_new;
  SetVelocityRhs(later_, free_rhs_);
  kkt_.Solve(free_rhs_, free_solution_);
  v_free_ = free_solution_.head(nv);
}

void FixedStepIntegrator::FinishStep(State& state, double h) {
  ScatterVelocities(system_, kkt_, v_free_, later_);
  v_free_ *= h;  // now the positions' displacement
  ApplyTreeDisplacement(system_, kkt_, v_free_, later_);
  later_.z += h * zdot_;
  ProjectAfterStep(later_, state.t);
  std::swap(state, later_);
}

bool FixedStepIntegrator::ProjectWithStartFactorization(State& later) {
  constexpr int kMaxIterations = 4;
  const int nv = kkt_.num_velocities();
  double previous = std::numeric_limits<double>::infinity();
  for (int iteration = 0; iteration <= kMaxIterations; ++iteration) {
    VecX& phi = phi_;
    // The step moved the bodies along the tree (ApplyTreeDisplacement); a Newton correction
    // moves them rigidly, which may leave any constraint.
    if (iteration == 0) {
      CalcPositionErrors(system_, later, phi, ErrorRows::kNotHeldByTree);
    } else {
      CalcPositionErrors(system_, later, phi);
    }
    const double error = phi.size() == 0 ? 0.0 : phi.lpNorm<Eigen::Infinity>();
    if (error <= ConstraintTolerance()) return true;
    if (!(error < 0.1 * previous)) {
      if (!(error < previous)) later = before_;
      return false;
    }
    if (iteration == kMaxIterations) return false;
    previous = error;
    before_ = later;
    rhs_.setZero(nv + phi.size());
    rhs_.tail(phi.size()) = -phi;
    kkt_.Solve(rhs_, solution_);
    step_ = solution_.head(nv);
    ApplyPositionDisplacement(system_, kkt_, step_, later);
  }
  return false;
}

bool FixedStepIntegrator::TryStartFactorization(State& later) {
  constexpr int kStepsWithoutAfterFailure = 16;
  if (steps_without_start_factorization_ > 0) {
    --steps_without_start_factorization_;
    return false;
  }
  if (ProjectWithStartFactorization(later)) return true;
  steps_without_start_factorization_ = kStepsWithoutAfterFailure;
  return false;
}

}  // namespace sinew::engine

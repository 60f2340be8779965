// The base of the schemes that advance by a fixed step `settings.step` ("euler",
// "implicit-euler", the NSC contact stepper): the step loop, and the projection of a step's
// result onto the constraints that reuses the step's first factorization.
#pragma once

#include <sinew/engine/integrator.h>

#include <string>

namespace sinew::engine {

/// An Integrator that takes steps of `settings.step` (the last step of a StepTo call shortened
/// to land exactly on t_final). Derived classes implement Step.
class FixedStepIntegrator : public Integrator {
 protected:
  /// Throws sinew::Error unless settings.step > 0; `name` is the scheme's, for messages.
  FixedStepIntegrator(const System& system, const IntegratorSettings& settings, const char* name);
  void TakeStep(State& state, double t_final) override;
  /// One step of length h from state.t, ending at time t_new.
  virtual void Step(State& state, double h, double t_new) = 0;

  /// Moves `later`, the state a step from `t_start` produced, onto the constraints (positions,
  /// velocities, direct coordinates), with kkt_ still factorized at the step's start. A
  /// fixed-step scheme cannot retry with a shorter step, so when the positions do not converge
  /// it throws a sinew::Error saying where and what to try.
  void ProjectAfterStep(State& later, double t_start);

  /// Writes every constraint's velocity right-hand side c at `later` (the step's end) into
  /// the constraint rows of `rhs` (nv + nc entries, KKT order), as the velocity-level step
  /// J v+ = c(t + h) needs.
  void SetVelocityRhs(const State& later, VecX& rhs) const;

  /// The scheme's name ("euler", ...).
  const std::string& name() const { return name_; }

  /// The first part of a semi-implicit Euler step from `state` to t_new = state.t + h:
  /// evaluates the loads there (its controller setting its inputs; kkt_ factorized at the step's
  /// start) and the state variables' derivatives (zdot_), keeps the start's velocities (v0_),
  /// and solves M v+ + J^T mu = M v0 + h f, J v+ = c(t_new) for v_free_ (f: the loads less the
  /// velocity terms; the same v+ as M v+ + J^T mu' = M (v0 + h vdot), one solve fewer).
  /// later_ is the state to finish, at t_new.
  void SolveFreeVelocities(State& state, double h, double t_new);
  /// Ends the step with the velocities v_free_: later_ takes them, its positions move by
  /// h v_free_ and its state variables by h zdot_, it is projected onto the constraints
  /// (ProjectAfterStep) and becomes `state`.
  void FinishStep(State& state, double h);

  // What SolveFreeVelocities leaves for the scheme and FinishStep; reused from step to step
  // (no heap use once sized).
  VecX zdot_, v0_, v_free_;
  State later_;

 private:
  // Newton iterations on phi(x) = 0 with the KKT matrix still factorized at the step's start:
  // a modified Newton method (the step moved the positions by h v, so the matrix is off by
  // O(h |v|) and each iteration divides the error by about 1 / (h |v| / length)). Returns true
  // once |phi| <= tolerance; false when an iteration does not cut the error tenfold, after
  // undoing an iteration that made it worse (ProjectPositions then goes on from there, with
  // fresh factorizations, as it would have from the start).
  bool ProjectWithStartFactorization(State& later);
  // ProjectWithStartFactorization, except for a while after it failed: where the stale matrix
  // does not converge fast (a long chain turning fast, whose Jacobian error grows along the
  // chain) every attempt would cost a solve for nothing.
  bool TryStartFactorization(State& later);

  std::string name_;
  int steps_without_start_factorization_ = 0;
  State before_;                      // the positions before the last start-factorization iteration
  VecX phi_, rhs_, solution_, step_;  // buffers of ProjectWithStartFactorization
  VecX force_rhs_, free_rhs_, free_solution_, mv_;  // buffers of SolveFreeVelocities
};

}  // namespace sinew::engine

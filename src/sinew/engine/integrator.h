// Time stepping. Four schemes share one interface:
// Auxiliary state variables z are integrated with the positions and velocities (under rk45's
// error control; by an explicit Euler step in the fixed-step schemes).
//  - "rk45": Dormand-Prince 5(4) with error control on positions and velocities and, after each
//    accepted step, projection of positions (Newton) and velocities (least squares) onto the
//    constraints. Used to match OpenSim's results.
//  - "cvode", "cvode-gmres", "cvode-gmres-bd": SUNDIALS CVODE's implicit BDF (orders 1-5,
//    Newton; dense difference-quotient Jacobian, or matrix-free GMRES, optionally
//    preconditioned by the auxiliary states' own block-diagonal Jacobian) with the same error
//    control target and projection (cvode_integrator.h): for stiff models (stiff tendons, fibers
//    far from equilibrium) where rk45's steps are bounded by stability.
//  - "euler": fixed-step semi-implicit (symplectic) Euler: the new velocities solve the
//    velocity-level KKT system M (v+ - v) = h f + J^T lambda, J v+ = c; positions then move
//    with v+ and are projected. First order, robust, one factorization per step (the velocity
//    projection's, which the next step's evaluation reuses; the position projection starts
//    from the step's first factorization): meant for non-smooth (contact) problems without
//    stiff forces.
//  - "implicit-euler": fixed-step linearized implicit Euler (force Jacobians by finite
//    differences, dense solve): stable for stiff springs and dampers on small models.
#pragma once

#include <sinew/engine/controller.h>
#include <sinew/engine/dynamics.h>
#include <sinew/engine/kkt.h>
#include <sinew/engine/loads.h>
#include <sinew/engine/projection.h>
#include <sinew/engine/state.h>
#include <sinew/engine/system.h>

#include <memory>
#include <string>

namespace sinew::engine {

/// Settings of an integrator.
struct IntegratorSettings {
  /// Relative local error allowed per step (with unit absolute floor), error-controlled only.
  double accuracy = 1e-6;
  /// Fixed step (s) of fixed-step schemes; upper bound of the step for error-controlled ones
  /// (0: no bound).
  double step = 0.0;
  /// Smallest step before giving up (s).
  double min_step = 1e-12;
  /// Constraint position tolerance of the projection (0: min(1e-3 accuracy, 1e-10)).
  double constraint_tolerance = 0.0;
};

/// Counters of an integrator's work.
struct IntegratorStats {
  long steps = 0;                      ///< accepted steps
  long rejected = 0;                   ///< rejected steps
  long evaluations = 0;                ///< acceleration evaluations
  long projection_factorizations = 0;  ///< KKT factorizations of the position projections
  long factorizations = 0;             ///< every KKT factorization (evaluations and projections)
  long projection_failures = 0;        ///< steps rejected because the projection did not converge
  long linear_iterations = 0;          ///< Krylov iterations of the Newton systems (cvode-gmres)
  long preconditioner_setups = 0;      ///< preconditioner evaluations (cvode-gmres-bd)
  /// Breakpoints crossed at a step's start (System::breakpoints, each coordinate's counted): a
  /// trial step across one that fails its error test is retried to end just short of it, and the
  /// next step crosses it with a tiny Euler step.
  long breakpoints_crossed = 0;
  /// Steps whose first stage was the last stage of the step before (rk45: no evaluation).
  long first_stages_reused = 0;
};

/// Advances a State of one System in time. Keeps a reference to the System: the System must
/// outlive the integrator and stay where it is (hold it by unique_ptr or in place).
class Integrator {
 public:
  virtual ~Integrator() = default;
  /// Advances `state` to exactly `t_final` (>= state.t). Throws sinew::Error on failure.
  /// After every accepted step the force elements' discrete data are updated
  /// (System::UpdateDiscreteData), and made first for elements the state has none of;
  /// Interpolate's states inside a step hold the data the step was taken with.
  void StepTo(State& state, double t_final);
  /// Takes one step from state.t, ending at or before `t_limit` (> state.t); steps are not
  /// shortened to land on intermediate times (see Interpolate). Throws sinew::Error on failure.
  void Advance(State& state, double t_limit);
  /// True when Interpolate can give states inside the last step (rk45, cvode: dense output).
  virtual bool HasDenseOutput() const { return false; }
  /// The state at time `t` inside the last step taken by Advance or StepTo (between its start
  /// and end), moved onto the constraints, written into `out` (any state of the system).
  /// Throws sinew::Error when the integrator has no dense output or t is outside the step.
  virtual void Interpolate(double t, State& out);
  /// Loads held constant and added to every evaluation (may be null; not owned). Call it again
  /// after changing them between steps.
  void SetExternalLoads(const Loads* loads) {
    external_ = loads;
    ++setup_changes_;
  }
  /// A controller that sets the inputs from time and state at every evaluation (null: the
  /// inputs keep the values the state holds). After each StepTo the state's inputs are the
  /// controller's at the final time.
  void SetController(std::shared_ptr<const Controller> controller) {
    controller_ = std::move(controller);
    ++setup_changes_;
  }
  const std::shared_ptr<const Controller>& controller() const { return controller_; }
  /// Sets `state`'s inputs from the controller (if any), as every evaluation does.
  void ApplyController(State& state) const;
  IntegratorStats stats() const {
    IntegratorStats stats = stats_;
    stats.factorizations = kkt_.num_factorizations();
    return stats;
  }
  const IntegratorSettings& settings() const { return settings_; }

 protected:
  Integrator(const System& system, const IntegratorSettings& settings);
  /// One step from state.t ending at or before t_limit (Advance without the checks).
  virtual void TakeStep(State& state, double t_limit) = 0;
  double ConstraintTolerance() const;
  /// One evaluation at `state`: inputs from the controller, then the accelerations (counted in
  /// stats().evaluations; the KKT factorization is reused when it was made at these positions)
  /// and, into `zdot`, the state variables' derivatives.
  const Accelerations& Evaluate(State& state, Eigen::Ref<VecX> zdot);
  /// Evaluate without the acceleration solve, for velocity-level steps: the same inputs, zdot
  /// and factorization, and into `force_rhs` the loads' rows of the KKT right-hand side
  /// (CalcForceRhsReusingFactorization).
  void EvaluateForces(State& state, Eigen::Ref<VecX> zdot, Eigen::Ref<VecX> force_rhs);

 private:
  // What both evaluations begin with: inputs from the controller, and the count.
  void ApplyInputs(State& state);

 protected:
  const System& system_;
  IntegratorSettings settings_;
  Data data_;       // the evaluations' workspace
  KktSolver& kkt_;  // data_.kkt
  const Loads* external_ = nullptr;
  std::shared_ptr<const Controller> controller_;
  IntegratorStats stats_;
  long setup_changes_ = 0;  // calls of SetExternalLoads and SetController
};

/// Makes the integrator named `name` ("rk45", "cvode", "cvode-gmres", "cvode-gmres-bd", "euler" or
/// "implicit-euler"; aliases "dopri5" and "semi-implicit-euler"). Throws sinew::Error for
/// another name.
std::unique_ptr<Integrator> MakeIntegrator(const std::string& name, const System& system,
                                           const IntegratorSettings& settings);

}  // namespace sinew::engine

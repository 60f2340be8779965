// SteppedCopy: one copy of a model advanced by fixed intervals h, what Simulator holds once and
// Batch n times. It has its own State and integrator (made again at every reset, so a run never
// depends on an earlier one, and the integrator's counters are those since the reset) and counts
// steps since the reset: step k ends at t_start + k h exactly, without accumulated rounding. The
// System is shared, read-only.
#pragma once

#include <sinew/engine/integrator.h>
#include <sinew/engine/state.h>
#include <sinew/engine/system.h>
#include <sinew/opensim/parser.h>

#include <memory>
#include <string>

namespace sinew::python {

class SteppedCopy {
 public:
  /// `system` as `parser` built it (its collision settings choose NSC stepping,
  /// opensim::MakeRunIntegrator). Throws sinew::Error for an unknown integrator or a step that
  /// is not > 0.
  SteppedCopy(const engine::System& system, const opensim::OpenSimParser& parser,
              const std::string& integrator, const engine::IntegratorSettings& settings,
              double interval);
  /// Starts again from `state` (checked against the system).
  void Reset(const engine::State& state);
  /// Sets the inputs to `controls` (system.num_inputs() values; null keeps them) and advances
  /// by one interval. Not thread-safe for one copy; copies may step on different threads.
  void Step(const double* controls);
  const engine::State& state() const { return state_; }
  /// The integrator of the steps since the last reset (its stats(), an NSC stepper's
  /// solve_summary()).
  const engine::Integrator& integrator() const { return *integrator_; }
  /// How many of its NSC steps above the solver's tolerance were already reported to Python
  /// (ReportNewUnconvergedSteps); 0 after a reset.
  long reported_unconverged() const { return reported_unconverged_; }
  void set_reported_unconverged(long steps) { reported_unconverged_ = steps; }

 private:
  const engine::System& system_;
  const opensim::OpenSimParser& parser_;
  std::string integrator_name_;
  engine::IntegratorSettings settings_;
  double interval_;
  std::unique_ptr<engine::Integrator> integrator_;
  engine::State state_;
  double t_start_ = 0.0;
  long steps_ = 0;
  long reported_unconverged_ = 0;
};

}  // namespace sinew::python

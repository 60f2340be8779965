// Simulate: the loop every front end shares (the CLI, the examples, Python): integrate a state
// over a duration and hand it to a reporter at regular report times. With rk45 the steps are
// not cut at report times: reported states come from its dense output, so loose accuracies
// take few steps whatever the report interval. A stop flag ends a run early and cleanly.
#pragma once

#include <sinew/engine/integrator.h>
#include <sinew/engine/state.h>

#include <atomic>
#include <functional>

namespace sinew::engine {

/// What Simulate does.
struct SimulationOptions {
  double duration = 0.0;          ///< simulated time (s), >= 0
  double report_interval = 0.01;  ///< time between reported states (s), > 0
  /// Checked after every step and every reported state: when it becomes true the run stops
  /// there (the states reported so far stand; the result says it stopped). May be null.
  const std::atomic<bool>* stop = nullptr;
  /// Called after every step with the fraction of the duration done and the time (may be
  /// empty).
  std::function<void(double fraction, double t)> progress;
};

/// How a run ended.
struct SimulationResult {
  bool completed = false;  ///< false when stopped by the stop flag
  long reports = 0;        ///< states handed to the reporter
};

/// Integrates `state` from state.t for options.duration with `integrator`, calling `report`
/// with the state at state.t, at every multiple of report_interval after it, and at the end
/// (the last interval may be shorter). Every reported state holds the inputs the integrator's
/// controller sets at its time (the first one too), so reported forces are those applied
/// (engine::ForceReporter gives them). On return `state` is the state at the end (or where the
/// run stopped). Throws sinew::Error for bad options or a failed step.
SimulationResult Simulate(Integrator& integrator, State& state, const SimulationOptions& options,
                          const std::function<void(const State&)>& report);

}  // namespace sinew::engine

#include <sinew/common/error.h>
#include <sinew/engine/simulation.h>

#include <algorithm>
#include <cmath>

namespace sinew::engine {

SimulationResult Simulate(Integrator& integrator, State& state, const SimulationOptions& options,
                          const std::function<void(const State&)>& report) {
  if (!(options.duration >= 0.0) || !std::isfinite(options.duration)) {
    throw Error("simulation: the duration must be finite and >= 0");
  }
  if (!(options.report_interval > 0.0) || !std::isfinite(options.report_interval)) {
    throw Error("simulation: the report interval must be finite and > 0");
  }
  const double t0 = state.t;
  const double t_end = t0 + options.duration;
  // Report times t0 + i * interval for i = 1..n, the last one clamped to t_end.
  const long n = static_cast<long>(std::ceil(options.duration / options.report_interval - 1e-9));
  auto report_time = [&](long i) { return std::min(t0 + i * options.report_interval, t_end); };
  SimulationResult result;
  auto stopped = [&] { return options.stop && options.stop->load(); };
  // The first reported state holds the inputs its first evaluation will see, as every later one
  // does (so reported actuator forces are the ones applied).
  integrator.ApplyController(state);
  report(state);
  ++result.reports;
  long next = 1;
  if (integrator.HasDenseOutput()) {
    State reported = state;
    while (next <= n) {
      integrator.Advance(state, t_end);
      // Every report time the step passed, from the step's dense output; the end itself
      // exactly.
      for (; next <= n && report_time(next) <= state.t; ++next) {
        if (report_time(next) == state.t) {
          report(state);
        } else {
          integrator.Interpolate(report_time(next), reported);
          report(reported);
          // One long step (a body at rest) may hold many report times: honour a stop between
          // them, the state then being the last one reported.
          if (stopped()) {
            ++result.reports;
            state = reported;
            return result;
          }
        }
        ++result.reports;
      }
      if (options.progress) options.progress((state.t - t0) / options.duration, state.t);
      if (next <= n && stopped()) return result;
    }
  } else {
    for (; next <= n; ++next) {
      integrator.StepTo(state, report_time(next));
      report(state);
      ++result.reports;
      if (options.progress) options.progress((state.t - t0) / options.duration, state.t);
      if (next < n && stopped()) return result;
    }
  }
  result.completed = true;
  return result;
}

}  // namespace sinew::engine

// The loop the muscle benchmarks share: one simulated second with the integrator `integrator`
// (rk45 unless named) from `start` per iteration, reporting simulated seconds per second and the
// average steps and evaluations.
#pragma once

#include <benchmark/benchmark.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/kkt.h>
#include <sinew/engine/state.h>
#include <sinew/engine/state_vector.h>
#include <sinew/engine/system.h>

#include <memory>
#include <string>

inline void RunOneSecond(benchmark::State& bench, const sinew::engine::System& system,
                         std::shared_ptr<const sinew::engine::Controller> controller,
                         const sinew::engine::State& start, double accuracy,
                         const std::string& integrator_name = "rk45") {
  double simulated = 0.0, steps = 0.0, evaluations = 0.0, linear_iterations = 0.0;
  for (auto _ : bench) {
    sinew::engine::State state = start;
    auto integrator =
        sinew::engine::MakeIntegrator(integrator_name, system, {.accuracy = accuracy});
    integrator->SetController(controller);
    integrator->StepTo(state, 1.0);
    simulated += 1.0;
    steps += static_cast<double>(integrator->stats().steps);
    evaluations += static_cast<double>(integrator->stats().evaluations);
    linear_iterations += static_cast<double>(integrator->stats().linear_iterations);
  }
  bench.counters["sim_s_per_s"] = benchmark::Counter(simulated, benchmark::Counter::kIsRate);
  bench.counters["steps"] = benchmark::Counter(steps, benchmark::Counter::kAvgIterations);
  bench.counters["evals"] = benchmark::Counter(evaluations, benchmark::Counter::kAvgIterations);
  if (linear_iterations > 0.0) {
    bench.counters["lin_iters"] =
        benchmark::Counter(linear_iterations, benchmark::Counter::kAvgIterations);
  }
  // The length of the integrated vector (cvode's Jacobian has as many columns).
  const sinew::engine::KktSolver kkt(system);
  bench.counters["n"] = sinew::engine::StateVector(system, kkt).size();
}

// One simulated second of the passive gait2354 and Rajagopal2016 skeletons (bodies, joints,
// coordinates and gravity only), and of Rajagopal2016 with its couplers, RK45 at accuracy 1e-6.
// From the default pose the skeleton falls as one rigid body (a parabola RK45 integrates in a
// few steps), so every coordinate is also given a speed of sin(c + 1) rad/s or m/s: the
// skeleton tumbles with all joints moving. Reports simulated seconds per wall second
// (sim_s_per_s) and steps per second. Both models are the copies in tests/data (gait2354 in
// opensim-core's test version of the file).
#include <benchmark/benchmark.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/dynamics.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/projection.h>
#include <sinew/io/osim_reader.h>
#include <sinew/opensim/build_system.h>
#include <sinew/opensim/parser.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <utility>

#include "engine/hung_skeleton.h"

namespace {

const std::string kData = SINEW_TEST_DATA_DIR;

// One second of `system` tumbling from its default pose with every coordinate given the speed
// sin(c + 1) (projected onto the constraints when it has extra ones), RK45 at accuracy 1e-6.
void RunTumbling(benchmark::State& bench, const sinew::engine::System& system) {
  double steps = 0.0, simulated = 0.0, evaluations = 0.0, rejected = 0.0, failures = 0.0;
  for (auto _ : bench) {
    sinew::engine::State state = sinew::engine::MakeDefaultState(system);
    for (int c = 0; c < system.num_coordinates(); ++c) state.u[c] = std::sin(c + 1.0);
    sinew::engine::PlaceBodies(system, state);
    if (system.HasExtraConstraints()) sinew::engine::ProjectState(system, state);
    sinew::engine::IntegratorSettings settings;
    settings.accuracy = 1e-6;
    auto integrator = sinew::engine::MakeIntegrator("rk45", system, settings);
    integrator->StepTo(state, 1.0);
    steps += static_cast<double>(integrator->stats().steps);
    evaluations += static_cast<double>(integrator->stats().evaluations);
    rejected += static_cast<double>(integrator->stats().rejected);
    failures += static_cast<double>(integrator->stats().projection_failures);
    simulated += 1.0;
  }
  bench.counters["sim_s_per_s"] = benchmark::Counter(simulated, benchmark::Counter::kIsRate);
  bench.counters["steps_per_s"] = benchmark::Counter(steps, benchmark::Counter::kIsRate);
  bench.counters["steps"] = benchmark::Counter(steps, benchmark::Counter::kAvgIterations);
  bench.counters["rejected"] = benchmark::Counter(rejected, benchmark::Counter::kAvgIterations);
  bench.counters["proj_fail"] = benchmark::Counter(failures, benchmark::Counter::kAvgIterations);
  bench.counters["evals"] = benchmark::Counter(evaluations, benchmark::Counter::kAvgIterations);
}

// The skeleton only (bodies, joints, coordinates, gravity).
void RunSkeleton(benchmark::State& bench, const std::string& file) {
  const sinew::model::ModelSpec spec = sinew::io::ReadOsim(file);
  RunTumbling(bench, *sinew::opensim::BuildSystem(spec));
}

void BM_Gait2354OneSecond(benchmark::State& bench) {
  RunSkeleton(bench,
              kData + "/opensim-org/opensim-core/OpenSim/Simulation/Test/gait2354_simbody.osim");
}
BENCHMARK(BM_Gait2354OneSecond)->Unit(benchmark::kMillisecond);

void BM_Rajagopal2016OneSecond(benchmark::State& bench) {
  RunSkeleton(bench, kData + "/opensim-org/opensim-models/Models/Rajagopal/Rajagopal2016.osim");
}
BENCHMARK(BM_Rajagopal2016OneSecond)->Unit(benchmark::kMillisecond);

// Rajagopal2016 through the OpenSim parser: the skeleton with its CoordinateCouplerConstraints
// (the patellae follow the knees) and its other forces; its 80 Millard2012 muscles are left out
// (--disable-force), so that this stays the skeleton's figure (bench_muscles_rajagopal has the
// muscles).
void BM_Rajagopal2016WithCouplersOneSecond(benchmark::State& bench) {
  const sinew::model::ModelSpec spec = sinew::io::ReadOsim(
      kData + "/opensim-org/opensim-models/Models/Rajagopal/Rajagopal2016.osim");
  sinew::OpenSimParser parser;
  for (const sinew::model::ForceSpec& force : spec.forces) {
    if (force.type == "Millard2012EquilibriumMuscle") parser.DisableForce(force.name);
  }
  sinew::engine::System system(spec.gravity);
  parser.ParseSpec(system, spec);
  system.Finalize();
  RunTumbling(bench, system);
}
BENCHMARK(BM_Rajagopal2016WithCouplersOneSecond)->Unit(benchmark::kMillisecond);

// Issue #15's accuracy benchmark (tests/engine/hung_skeleton.h): one simulated second of a hung
// skeleton with RK45 at accuracy 10^-k (`rk45`, k = the benchmark's argument) or 10^(-k/4)
// (`sweep`: quarter decades, from which benchmarks/fit_hung_sweep.py reads the time at a given
// error). The error is measured, not assumed: `err_rad` is the largest |q - q_ref| over the
// coordinates at 1 s, q_ref from a run at accuracy 1e-12 made once per model before timing. The
// issue compares the time at the accuracy whose error is 3e-6 rad with Simbody's;
// simbody_hung.cc times Simbody on the same motion.
using sinew::engine::testing::HungSkeleton;
using sinew::engine::testing::MakeHungSkeleton;
using sinew::engine::testing::RunHung;

// A hung skeleton with its reference end state, made once per model.
struct HungCase {
  explicit HungCase(HungSkeleton skeleton)
      : hung(std::move(skeleton)), reference(RunHung(hung, "rk45", 1e-12, nullptr)) {}
  HungSkeleton hung;
  sinew::engine::State reference;
};

// Arguments per decade of accuracy: 1 for `rk45`, 4 for `sweep`.
void TimeHung(benchmark::State& bench, const HungCase& model, double args_per_decade) {
  const double accuracy = std::pow(10.0, -static_cast<double>(bench.range(0)) / args_per_decade);
  sinew::engine::IntegratorStats stats;
  sinew::engine::State state;
  for (auto _ : bench) {
    state = RunHung(model.hung, "rk45", accuracy, &stats);
    benchmark::DoNotOptimize(state.q.data());
  }
  bench.counters["err_rad"] = (state.q - model.reference.q).lpNorm<Eigen::Infinity>();
  bench.counters["steps"] = static_cast<double>(stats.steps);
  bench.counters["rejected"] = static_cast<double>(stats.rejected);
  bench.counters["evaluations"] = static_cast<double>(stats.evaluations);
  bench.counters["factorizations"] = static_cast<double>(stats.factorizations);
}

void BM_Gait2354HungOneSecond(benchmark::State& bench, double args_per_decade) {
  static const HungCase model(
      MakeHungSkeleton(sinew::engine::testing::kGait2354HungFile, false, -1.0));
  TimeHung(bench, model, args_per_decade);
}
BENCHMARK_CAPTURE(BM_Gait2354HungOneSecond, rk45, 1.0)
    ->DenseRange(6, 9)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Gait2354HungOneSecond, sweep, 4.0)
    ->DenseRange(20, 40)
    ->Unit(benchmark::kMillisecond);

// Rajagopal2016 hung the same way, with its patella couplers (its 80 muscles left out).
void BM_Rajagopal2016HungOneSecond(benchmark::State& bench, double args_per_decade) {
  static const HungCase model(
      MakeHungSkeleton(sinew::engine::testing::kRajagopal2016HungFile, true, 1.0));
  TimeHung(bench, model, args_per_decade);
}
BENCHMARK_CAPTURE(BM_Rajagopal2016HungOneSecond, rk45, 1.0)
    ->DenseRange(6, 9)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Rajagopal2016HungOneSecond, sweep, 4.0)
    ->DenseRange(20, 40)
    ->Unit(benchmark::kMillisecond);

// One acceleration evaluation (loads, KKT factorization, solve) of the tumbling gait2354
// skeleton: the figure the engine's speed goal (10 us on a gait2392-size skeleton) is about.
void BM_Gait2354Accelerations(benchmark::State& bench) {
  const sinew::model::ModelSpec spec = sinew::io::ReadOsim(
      kData + "/opensim-org/opensim-core/OpenSim/Simulation/Test/gait2354_simbody.osim");
  const auto system = sinew::opensim::BuildSystem(spec);
  sinew::engine::State state = sinew::engine::MakeDefaultState(*system);
  for (int c = 0; c < system->num_coordinates(); ++c) state.u[c] = std::sin(c + 1.0);
  sinew::engine::PlaceBodies(*system, state);
  sinew::engine::Data data(*system);
  for (auto _ : bench) {
    benchmark::DoNotOptimize(sinew::engine::CalcAccelerations(*system, state, nullptr, data));
  }
}
BENCHMARK(BM_Gait2354Accelerations)->Unit(benchmark::kMicrosecond);

// Fixed steps (h = 1 ms) of semi-implicit Euler on chrono's Rajagopal2015.osim skeleton from
// the tumbling state, `steps` per iteration (each iteration starts again from that state, as
// the chain benchmarks do); the time is per step.
void TimeEulerSteps(benchmark::State& bench, int steps) {
  const sinew::model::ModelSpec spec =
      sinew::io::ReadOsim(kData + "/projectchrono/chrono/data/opensim/Rajagopal2015.osim");
  const auto system = sinew::opensim::BuildSystem(spec);
  sinew::engine::State start = sinew::engine::MakeDefaultState(*system);
  for (int c = 0; c < system->num_coordinates(); ++c) start.u[c] = std::sin(c + 1.0);
  sinew::engine::PlaceBodies(*system, start);
  sinew::engine::IntegratorSettings settings;
  settings.step = 1e-3;
  auto integrator = sinew::engine::MakeIntegrator("euler", *system, settings);
  for (auto _ : bench) {
    sinew::engine::State state = start;
    integrator->StepTo(state, start.t + steps * 1e-3);
    benchmark::DoNotOptimize(state.bodies.data());
  }
  const double total = static_cast<double>(bench.iterations()) * steps;
  bench.counters["proj_factorizations"] = benchmark::Counter(
      static_cast<double>(integrator->stats().projection_factorizations) / total);
  bench.counters["factorizations"] =
      benchmark::Counter(static_cast<double>(integrator->stats().factorizations) / total);
  bench.SetItemsProcessed(bench.iterations() * steps);
}

// One step: its evaluation cannot reuse a factorization (the previous iteration ended
// elsewhere).
void BM_Rajagopal2015EulerStep(benchmark::State& bench) { TimeEulerSteps(bench, 1); }
BENCHMARK(BM_Rajagopal2015EulerStep)->Unit(benchmark::kMicrosecond);

// 100 steps (0.1 s): the steady state, where each step's evaluation reuses the previous
// step's velocity-projection factorization. Time per step = the time / 100 (items_per_second).
void BM_Rajagopal2015EulerHundredSteps(benchmark::State& bench) { TimeEulerSteps(bench, 100); }
BENCHMARK(BM_Rajagopal2015EulerHundredSteps)->Unit(benchmark::kMillisecond);

}  // namespace

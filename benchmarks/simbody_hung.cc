// Issue #15's speed goal compares Sinew with Simbody, the engine under OpenSim, on the hung
// skeletons of tests/engine/hung_skeleton.h. This program times Simbody itself (Debian's
// libsimbody 3.7, or any Simbody 3.7 found first by the loader) on the same motion, on the same
// machine, so the ratio is measured, not carried over from another machine. The model is built
// as reference/simbody/from_spec.h says, with the mobilizers OpenSim gives the joints; the
// start pose and speeds are the Sinew benchmark's.
//
// Reported: CPU time for one simulated second with Simbody's RungeKuttaMersonIntegrator
// (OpenSim's default; `merson`) or RungeKuttaFeldbergIntegrator (`feldberg`) at accuracy 10^-k
// (k = the argument), or RK Merson at 10^(-k/4) (`merson_sweep`: quarter decades, read by
// benchmarks/fit_hung_sweep.py); `err_rad`, the largest coordinate error at 1 s against a Simbody
// run at accuracy 1e-12; `vs_sinew_rad`, how far that Simbody reference lies from Sinew's own at
// 1e-12; `energy_change_J`, how much mechanical energy that reference gained (nothing but
// gravity acts: it should be zero to the integration's error); `steps`, `rejected` and
// `evaluations` (realizations), what the integrator did. CPU time at the accuracy whose error is
// 3e-6 rad is what the goal compares with `BM_Gait2354HungOneSecond`.
#include <benchmark/benchmark.h>
#include <sinew/common/error.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "engine/hung_skeleton.h"
#include "simbody/from_spec.h"

namespace {

using simbody_reference::MaxDifference;
using simbody_reference::ToSimbody;

// A hung skeleton in Simbody with its references, made once per model.
struct SimbodyCase {
  explicit SimbodyCase(sinew::engine::testing::HungSkeleton skeleton)
      : hung(std::move(skeleton)), simulation(ToSimbody(hung.spec, hung.start)) {
    simbody_reference::Simulation::RunStats stats;
    reference = simulation.Run(simbody_reference::Simulation::Scheme::kRungeKuttaMerson, 1e-12, 1.0,
                               &stats);
    energy_change = stats.energy_change;
    vs_sinew =
        MaxDifference(reference, sinew::engine::testing::RunHung(hung, "rk45", 1e-12, nullptr).q);
  }
  sinew::engine::testing::HungSkeleton hung;
  simbody_reference::Simulation simulation;
  std::vector<double> reference;  // Simbody at accuracy 1e-12
  double energy_change = 0.0;     // of that reference run
  double vs_sinew = 0.0;          // its largest difference from Sinew's at 1e-12
};

void TimeSimbody(benchmark::State& bench, const SimbodyCase& model,
                 simbody_reference::Simulation::Scheme scheme, double args_per_decade) {
  const double accuracy = std::pow(10.0, -static_cast<double>(bench.range(0)) / args_per_decade);
  simbody_reference::Simulation::RunStats stats;
  std::vector<double> q;
  for (auto _ : bench) {
    q = model.simulation.Run(scheme, accuracy, 1.0, &stats);
    benchmark::DoNotOptimize(q.data());
  }
  const Eigen::VectorXd reference = Eigen::Map<const Eigen::VectorXd>(
      model.reference.data(), static_cast<Eigen::Index>(model.reference.size()));
  bench.counters["err_rad"] = MaxDifference(q, reference);
  bench.counters["vs_sinew_rad"] = model.vs_sinew;
  bench.counters["energy_change_J"] = model.energy_change;
  bench.counters["steps"] = static_cast<double>(stats.steps);
  bench.counters["rejected"] = static_cast<double>(stats.attempted - stats.steps);
  bench.counters["evaluations"] = static_cast<double>(stats.realizations);
}

using Scheme = simbody_reference::Simulation::Scheme;

void BM_SimbodyGait2354HungOneSecond(benchmark::State& bench, Scheme scheme,
                                     double args_per_decade) {
  static const SimbodyCase model(sinew::engine::testing::MakeHungSkeleton(
      sinew::engine::testing::kGait2354HungFile, false, -1.0));
  TimeSimbody(bench, model, scheme, args_per_decade);
}
BENCHMARK_CAPTURE(BM_SimbodyGait2354HungOneSecond, merson, Scheme::kRungeKuttaMerson, 1.0)
    ->DenseRange(5, 9)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SimbodyGait2354HungOneSecond, feldberg, Scheme::kRungeKuttaFeldberg, 1.0)
    ->DenseRange(5, 11)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SimbodyGait2354HungOneSecond, merson_sweep, Scheme::kRungeKuttaMerson, 4.0)
    ->DenseRange(28, 40)
    ->Unit(benchmark::kMillisecond);

void BM_SimbodyRajagopal2016HungOneSecond(benchmark::State& bench, Scheme scheme,
                                          double args_per_decade) {
  static const SimbodyCase model(sinew::engine::testing::MakeHungSkeleton(
      sinew::engine::testing::kRajagopal2016HungFile, true, 1.0));
  TimeSimbody(bench, model, scheme, args_per_decade);
}
BENCHMARK_CAPTURE(BM_SimbodyRajagopal2016HungOneSecond, merson, Scheme::kRungeKuttaMerson, 1.0)
    ->DenseRange(5, 9)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SimbodyRajagopal2016HungOneSecond, feldberg, Scheme::kRungeKuttaFeldberg, 1.0)
    ->DenseRange(5, 10)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SimbodyRajagopal2016HungOneSecond, merson_sweep, Scheme::kRungeKuttaMerson,
                  4.0)
    ->DenseRange(20, 36)
    ->Unit(benchmark::kMillisecond);

// One acceleration evaluation of the tumbling gait2354 skeleton in Simbody: the counterpart of
// `BM_Gait2354Accelerations` (the same file, pose and speeds sin(c + 1); issue #15 quotes about
// 70 us for Simbody on a model of this size). Everything from the positions on is recomputed.
void BM_SimbodyGait2354Accelerations(benchmark::State& bench) {
  const sinew::model::ModelSpec spec = sinew::io::ReadOsim(
      std::string(SINEW_TEST_DATA_DIR) +
      "/opensim-org/opensim-core/OpenSim/Simulation/Test/gait2354_simbody.osim");
  const auto system = sinew::opensim::BuildSystem(spec);
  sinew::engine::State state = sinew::engine::MakeDefaultState(*system);
  for (int c = 0; c < system->num_coordinates(); ++c) state.u[c] = std::sin(c + 1.0);
  sinew::engine::PlaceBodies(*system, state);
  const simbody_reference::Simulation simulation(ToSimbody(spec, state, false));
  for (auto _ : bench) benchmark::DoNotOptimize(simulation.EvaluateAccelerations());
}
BENCHMARK(BM_SimbodyGait2354Accelerations);

}  // namespace

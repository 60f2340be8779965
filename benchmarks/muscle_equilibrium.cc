// The cost of the muscle mathematics the muscle element calls at every evaluation and at
// initialization: one Millard2012 curve value, one Millard2012 state (fiber velocity by the
// damped Newton iteration, forces), one Millard2012 equilibrium solve, and DeGroote's.
#include <benchmark/benchmark.h>
#include <sinew/io/osim_reader.h>
#include <sinew/muscles/degroote_fregly2016_muscle.h>
#include <sinew/muscles/millard2012_equilibrium.h>
#include <sinew/muscles/millard2012_spec.h>

#include <string>
#include <vector>

namespace {

using namespace sinew::muscles;

// Gait10dof18musc's 18 Millard2012 muscles (as in the MyoConverter reference test).
const std::vector<Millard2012Muscle>& GaitMuscles() {
  static const std::vector<Millard2012Muscle> muscles = [] {
    const std::string osim =
        std::string(SINEW_TEST_DATA_DIR) +
        "/MyoHub/myoconverter/models/osim/Gait10dof18musc/gait10dof18musc.osim";
    const sinew::model::ModelSpec spec = sinew::io::ReadOsim(osim);
    std::vector<Millard2012Muscle> out;
    for (const sinew::model::ForceSpec& f : spec.forces) {
      if (f.type == "Millard2012EquilibriumMuscle") out.push_back(ReadMillard2012Muscle(spec, f));
    }
    return out;
  }();
  return muscles;
}

// Path lengths that put each muscle's fiber near its optimal length (slack + optimal, cos 0.95).
double RestingPathLength(const Millard2012Muscle& m) {
  return m.parameters().tendon_slack_length * 1.02 + m.parameters().optimal_fiber_length * 0.95;
}

void BM_Millard2012CurveValue(benchmark::State& state) {
  const Millard2012Muscle& m = GaitMuscles().front();
  double x = 0.8;
  for (auto _ : state) {
    benchmark::DoNotOptimize(m.active_force_length().ValueAndDerivative(x));
    x = x < 1.2 ? x + 1e-3 : 0.8;
  }
}
BENCHMARK(BM_Millard2012CurveValue);

// All 18 muscles' states (what a model evaluation asks of them), per muscle.
void BM_Millard2012Dynamics(benchmark::State& state) {
  const std::vector<Millard2012Muscle>& muscles = GaitMuscles();
  std::vector<double> fiber_lengths, paths;
  for (const Millard2012Muscle& m : muscles) {
    paths.push_back(RestingPathLength(m));
    fiber_lengths.push_back(SolveMillard2012Equilibrium(m, 0.5, paths.back(), 0.0).fiber_length);
  }
  for (auto _ : state) {
    for (size_t i = 0; i < muscles.size(); ++i) {
      benchmark::DoNotOptimize(
          CalcMillard2012Dynamics(muscles[i], 0.5, fiber_lengths[i] * 1.01, paths[i], 0.05));
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(muscles.size()));
}
BENCHMARK(BM_Millard2012Dynamics);

void BM_Millard2012Equilibrium(benchmark::State& state) {
  const std::vector<Millard2012Muscle>& muscles = GaitMuscles();
  for (auto _ : state) {
    for (const Millard2012Muscle& m : muscles) {
      benchmark::DoNotOptimize(SolveMillard2012Equilibrium(m, 0.5, RestingPathLength(m), 0.0));
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(muscles.size()));
}
BENCHMARK(BM_Millard2012Equilibrium);

void BM_DeGrooteFregly2016Equilibrium(benchmark::State& state) {
  DeGrooteFregly2016Parameters p;
  p.optimal_fiber_length = 0.1;
  p.tendon_slack_length = 0.2;
  p.pennation_angle_at_optimal = 0.2;
  const DeGrooteFregly2016Muscle m(p);
  for (auto _ : state) {
    benchmark::DoNotOptimize(SolveDeGrooteFregly2016Equilibrium(m, 0.5, 0.3, 0.0));
  }
}
BENCHMARK(BM_DeGrooteFregly2016Equilibrium);

void BM_DeGrooteFregly2016Dynamics(benchmark::State& state) {
  DeGrooteFregly2016Parameters p;
  p.pennation_angle_at_optimal = 0.2;
  const DeGrooteFregly2016Muscle m(p);
  for (auto _ : state) {
    benchmark::DoNotOptimize(CalcDeGrooteFregly2016Dynamics(m, 0.5, 0.4, 0.3, 0.05));
  }
}
BENCHMARK(BM_DeGrooteFregly2016Dynamics);

}  // namespace

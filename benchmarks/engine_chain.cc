// N-link pendulum chain (tests/engine/chain_model.h: direct pins alternating about z and x,
// 0.1 m links): the cost of one acceleration evaluation (KKT assembly + tree solve) and
// of one fixed step, for N = 10, 100, 1000. Tree-structured, so the cost should grow linearly with
// N.
//
// The step benchmarks time a step from the default state every iteration, so the work measured
// does not depend on how many iterations the benchmark library chooses (letting the chain move
// on would time steps ever further into a violent motion: at N = 1000 the outer links soon turn
// at over 100 rad/s, and by t = 0.066 s a 1 ms Euler step leaves constraint errors of ~5 cm for
// the projection to remove). The state copy this needs is a small part of a step. An integrator
// failure (a sinew::Error) ends the benchmark with an error instead of aborting the program.
#include <benchmark/benchmark.h>
#include <sinew/common/error.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/dynamics.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/system.h>

#include <cmath>

#include "engine/chain_model.h"

namespace {

using namespace sinew;
using namespace sinew::engine;

using sinew::engine::testing::MakeChain;

// Times `integrator` advancing a copy of `start` by 1 ms, once per benchmark iteration. On a
// sinew::Error reports it (SkipWithError) and returns false.
bool TimeSteps(benchmark::State& bench, Integrator& integrator, const State& start) {
  try {
    for (auto _ : bench) {
      State state = start;
      integrator.StepTo(state, start.t + 1e-3);
      benchmark::DoNotOptimize(state.bodies.data());
    }
  } catch (const sinew::Error& e) {
    bench.SkipWithError(e.what());
    return false;
  }
  return true;
}

// Times one acceleration evaluation of `system` from its default state.
void TimeAccelerations(benchmark::State& bench, const System& system) {
  const State state = MakeDefaultState(system);
  Data data(system);
  for (auto _ : bench) {
    benchmark::DoNotOptimize(CalcAccelerations(system, state, nullptr, data));
  }
  bench.SetComplexityN(bench.range(0));
}

void BM_ChainAccelerations(benchmark::State& bench) {
  TimeAccelerations(bench, MakeChain(static_cast<int>(bench.range(0)), JointForm::kPin));
}
BENCHMARK(BM_ChainAccelerations)
    ->Arg(10)
    ->Arg(100)
    ->Arg(1000)
    ->Unit(benchmark::kMicrosecond)
    ->Complexity(benchmark::oN);

// The chain with parameterized pins (RevoluteModel, articulated pivots) and no extra
// constraints: the baseline of the coupled chain below, whose couplers' own cost is the
// difference of the two.
void BM_ParameterizedChainAccelerations(benchmark::State& bench) {
  TimeAccelerations(bench, MakeChain(static_cast<int>(bench.range(0)), JointForm::kParameterized));
}
BENCHMARK(BM_ParameterizedChainAccelerations)
    ->Arg(10)
    ->Arg(100)
    ->Arg(1000)
    ->Unit(benchmark::kMicrosecond)
    ->Complexity(benchmark::oN);

// The same with parameterized pins and 4 couplers (q[i] = 0.5 q[i + N/2]) solved by the
// Schur complement beside the tree elimination: still linear in N.
void BM_CoupledChainAccelerations(benchmark::State& bench) {
  TimeAccelerations(bench,
                    MakeChain(static_cast<int>(bench.range(0)), JointForm::kParameterized, 4));
}
BENCHMARK(BM_CoupledChainAccelerations)
    ->Arg(10)
    ->Arg(100)
    ->Arg(1000)
    ->Unit(benchmark::kMicrosecond)
    ->Complexity(benchmark::oN);

// The chain of direct pins with 4 rods between links half a chain apart (ConstantDistance
// constraints, one row each), solved by the Schur complement beside the tree elimination: the
// plain chain's joints with a few extra constraints, still linear in N.
void BM_ChainWithRodsAccelerations(benchmark::State& bench) {
  TimeAccelerations(bench, MakeChain(static_cast<int>(bench.range(0)), JointForm::kPin, 0, 4));
}
BENCHMARK(BM_ChainWithRodsAccelerations)
    ->Arg(10)
    ->Arg(100)
    ->Arg(1000)
    ->Unit(benchmark::kMicrosecond)
    ->Complexity(benchmark::oN);

// One RK45 step (7 evaluations, position and velocity projection), step fixed at 1 ms.
void BM_ChainRk45Step(benchmark::State& bench) {
  const System system = MakeChain(static_cast<int>(bench.range(0)), JointForm::kPin);
  const State state = MakeDefaultState(system);
  IntegratorSettings settings;
  settings.accuracy = 1e-2;  // loose: every step of 1 ms is accepted
  settings.step = 1e-3;
  auto integrator = MakeIntegrator("rk45", system, settings);
  if (!TimeSteps(bench, *integrator, state)) return;
  bench.counters["rejected"] = static_cast<double>(integrator->stats().rejected);
  bench.counters["proj_factorizations"] =
      benchmark::Counter(static_cast<double>(integrator->stats().projection_factorizations),
                         benchmark::Counter::kAvgIterations);
  bench.SetComplexityN(bench.range(0));
}
BENCHMARK(BM_ChainRk45Step)
    ->Arg(10)
    ->Arg(100)
    ->Arg(1000)
    ->Unit(benchmark::kMicrosecond)
    ->Complexity(benchmark::oN);

// One semi-implicit Euler step (one KKT solve, projection) of 1 ms.
void BM_ChainEulerStep(benchmark::State& bench) {
  const System system = MakeChain(static_cast<int>(bench.range(0)), JointForm::kPin);
  const State state = MakeDefaultState(system);
  IntegratorSettings settings;
  settings.step = 1e-3;
  auto integrator = MakeIntegrator("euler", system, settings);
  if (!TimeSteps(bench, *integrator, state)) return;
  bench.counters["proj_factorizations"] =
      benchmark::Counter(static_cast<double>(integrator->stats().projection_factorizations),
                         benchmark::Counter::kAvgIterations);
  bench.SetComplexityN(bench.range(0));
}
BENCHMARK(BM_ChainEulerStep)
    ->Arg(10)
    ->Arg(100)
    ->Arg(1000)
    ->Unit(benchmark::kMicrosecond)
    ->Complexity(benchmark::oN);

}  // namespace

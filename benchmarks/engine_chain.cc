// N-link pendulum chain (direct pins alternating about z and x, 0.1 m links): the cost of one
// acceleration evaluation (KKT assembly + sparse LU + solve) and of one fixed step, for
// N = 10, 100, 1000. Tree-structured, so the cost should grow linearly with N.
#include <benchmark/benchmark.h>

#include <cmath>

#include <sinew/engine/assemble.h>
#include <sinew/engine/dynamics.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/system.h>

namespace {

using namespace sinew;
using namespace sinew::engine;

System MakeChain(int n, JointForm form) {
  System system(Vec3(0, -9.81, 0));
  const Mat3 y_to_z = Eigen::AngleAxisd(M_PI / 2, Vec3::UnitY()).toRotationMatrix();
  int parent = 0;
  for (int i = 0; i < n; ++i) {
    Body body;
    body.name = "link" + std::to_string(i);
    body.mass = 0.5;
    body.p_BCm = Vec3(0, -0.05, 0);
    body.I_Bcm_B = Vec3(4e-4, 1e-4, 4e-4).asDiagonal();
    const int b = system.AddBody(body);
    // Odd joints turn about x: rotate F and M so that their z axis is the body's x.
    const Mat3 R = (i % 2 == 0) ? Mat3::Identity() : y_to_z;
    const Transform X_PF(R, parent == 0 ? Vec3::Zero() : Vec3(0, -0.1, 0));
    CoordinateDesc c;
    c.name = "q" + std::to_string(i);
    c.default_value = 0.1;
    c.default_speed = 0.2;
    system.AddJoint("pin" + std::to_string(i), parent, X_PF, b, Transform::Rotation(R), form,
                    nullptr, {c});
    parent = b;
  }
  system.Finalize();
  return system;
}

void BM_ChainAccelerations(benchmark::State& bench) {
  const System system = MakeChain(static_cast<int>(bench.range(0)), JointForm::kPin);
  const State state = MakeDefaultState(system);
  KktSolver kkt(system);
  for (auto _ : bench) {
    benchmark::DoNotOptimize(CalcAccelerations(system, state, nullptr, kkt));
  }
  bench.SetComplexityN(bench.range(0));
}
BENCHMARK(BM_ChainAccelerations)
    ->Arg(10)
    ->Arg(100)
    ->Arg(1000)
    ->Unit(benchmark::kMicrosecond)
    ->Complexity(benchmark::oN);

// One RK45 step (7 evaluations, position and velocity projection), step fixed at 1 ms.
void BM_ChainRk45Step(benchmark::State& bench) {
  const System system = MakeChain(static_cast<int>(bench.range(0)), JointForm::kPin);
  State state = MakeDefaultState(system);
  IntegratorSettings settings;
  settings.accuracy = 1e-2;  // loose: every step of 1 ms is accepted
  settings.step = 1e-3;
  auto integrator = MakeIntegrator("rk45", system, settings);
  for (auto _ : bench) integrator->StepTo(state, state.t + 1e-3);
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
  State state = MakeDefaultState(system);
  IntegratorSettings settings;
  settings.step = 1e-3;
  auto integrator = MakeIntegrator("euler", system, settings);
  for (auto _ : bench) integrator->StepTo(state, state.t + 1e-3);
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

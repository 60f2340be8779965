// OpenSim's bouncing balls (tests/data: BouncingBall_HuntCrossley.osim, BouncingBallModelEF.osim
// with its 720-face mesh, BouncingBall_SmoothSphereHalfSpace.osim), resting in contact on their
// floor: the cost of one acceleration evaluation (contact force included), of one fixed 1 ms
// semi-implicit Euler step, and of one simulated second of a drop from 1 m with rk45 at 1e-6.
#include <benchmark/benchmark.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/dynamics.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/system.h>
#include <sinew/opensim/parser.h>

#include <memory>
#include <string>

namespace {

using namespace sinew;

const std::string kTests =
    std::string(SINEW_TEST_DATA_DIR) + "/opensim-org/opensim-core/OpenSim/Simulation/Test/";
const char* const kModels[] = {"BouncingBall_HuntCrossley.osim", "BouncingBallModelEF.osim",
                               "BouncingBall_SmoothSphereHalfSpace.osim"};

std::unique_ptr<engine::System> Parse(const benchmark::State& bench) {
  opensim::OpenSimParser parser;
  return parser.Parse(kTests + kModels[bench.range(0)]);
}

// The ball resting half a millimetre into its floor (in contact), at rest.
engine::State RestingState(const engine::System& system) {
  engine::State state = engine::MakeDefaultState(system);
  engine::SetCoordinateValue(system, state, "ball_ty", 0.4995);
  return state;
}

void BM_BallAccelerations(benchmark::State& bench) {
  const auto system = Parse(bench);
  const engine::State state = RestingState(*system);
  engine::Data data(*system);
  for (auto _ : bench) benchmark::DoNotOptimize(engine::CalcAccelerations(*system, state, nullptr, data));
  bench.SetLabel(kModels[bench.range(0)]);
}
BENCHMARK(BM_BallAccelerations)->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);

void BM_BallEulerStep(benchmark::State& bench) {
  const auto system = Parse(bench);
  const engine::State start = RestingState(*system);
  engine::IntegratorSettings settings;
  settings.step = 1e-3;
  auto integrator = engine::MakeIntegrator("euler", *system, settings);
  for (auto _ : bench) {
    engine::State state = start;
    integrator->StepTo(state, 1e-3);
    benchmark::DoNotOptimize(state.bodies.data());
  }
  bench.SetLabel(kModels[bench.range(0)]);
}
BENCHMARK(BM_BallEulerStep)->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);

void BM_BallDropOneSecond(benchmark::State& bench) {
  const auto system = Parse(bench);
  engine::State start = engine::MakeDefaultState(*system);
  engine::SetCoordinateValue(*system, start, "ball_ty", 1.0);
  engine::IntegratorSettings settings;
  settings.accuracy = 1e-6;
  auto integrator = engine::MakeIntegrator("rk45", *system, settings);
  for (auto _ : bench) {
    engine::State state = start;
    integrator->StepTo(state, 1.0);
    benchmark::DoNotOptimize(state.bodies.data());
  }
  bench.SetLabel(kModels[bench.range(0)]);
}
BENCHMARK(BM_BallDropOneSecond)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

}  // namespace

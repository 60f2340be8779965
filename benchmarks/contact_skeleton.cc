// The skeleton-on-ground scene with SMC contact (the benchmark, the seed's Chrono scene:
// Rajagopal2015's skeleton, its collision cylinders, a ground plane): microseconds per step of
// semi-implicit Euler at h = 1e-3 s over the first second after a 5 cm drop (it lands and
// collapses, so contacts come and go). The scene is the one of
// tests/contact/skeleton_drop_test.cc.
#include <benchmark/benchmark.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/integrator.h>

#include "contact/skeleton_drop.h"

namespace {

// One simulated second of `system` from its default state with the fixed-step `scheme` at
// h = 1e-3 s per iteration; reports microseconds per step and the steps.
void TimeOneSecond(benchmark::State& bench, const sinew::engine::System& system,
                   const char* scheme) {
  double steps = 0.0;
  for (auto _ : bench) {
    sinew::engine::State state = sinew::engine::MakeDefaultState(system);
    sinew::engine::IntegratorSettings settings;
    settings.step = 1e-3;
    auto integrator = sinew::engine::MakeIntegrator(scheme, system, settings);
    integrator->StepTo(state, 1.0);
    steps += static_cast<double>(integrator->stats().steps);
  }
  bench.counters["us_per_step"] =
      benchmark::Counter(steps * 1e-6, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  bench.counters["steps"] = benchmark::Counter(steps, benchmark::Counter::kAvgIterations);
}

// Argument 1: the ground is a box (the seed's scene literally, `AddEnvironmentBox`), whose top
// face the cylinders touch as a plane there.
void BM_SkeletonOnGroundSmcStep(benchmark::State& bench) {
  const sinew::testing::SkeletonDrop scene =
      sinew::testing::MakeSkeletonDrop(0.05, {}, bench.range(0) == 1);
  TimeOneSecond(bench, *scene.system, "euler");
}
BENCHMARK(BM_SkeletonOnGroundSmcStep)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// The same scene on the plane with tangential springs (kt = 1e7 Pa, gt = 20 N s/m): the
// contacts' displacements are kept from step to step, which finds the contacts once more per
// step (SmoothCollisionForce::UpdateDiscreteData).
void BM_SkeletonOnGroundSmcTangentialSpringStep(benchmark::State& bench) {
  sinew::contact::CollisionMaterial material;
  material.kt = 1e7;
  material.gt = 20.0;
  const sinew::testing::SkeletonDrop scene = sinew::testing::MakeSkeletonDrop(0.05, material);
  TimeOneSecond(bench, *scene.system, "euler");
}
BENCHMARK(BM_SkeletonOnGroundSmcTangentialSpringStep)->Unit(benchmark::kMillisecond);

// The same scene with linearized implicit Euler, which comes to rest there at 1 ms where
// semi-implicit Euler does not (docs/contact.md): the SMC force's own load Jacobians and a
// sparse LU of the step's KKT matrix.
void BM_SkeletonOnGroundSmcImplicitEulerStep(benchmark::State& bench) {
  const sinew::testing::SkeletonDrop scene = sinew::testing::MakeSkeletonDrop(0.05);
  TimeOneSecond(bench, *scene.system, "implicit-euler");
}
BENCHMARK(BM_SkeletonOnGroundSmcImplicitEulerStep)->Unit(benchmark::kMillisecond);

// The same skeleton in free fall without collision (its evaluation, KKT solve and projections
// alone): what the contact adds is the difference.
void BM_SkeletonFallingWithoutCollisionStep(benchmark::State& bench) {
  sinew::model::ModelSpec spec = sinew::io::ReadOsim(
      std::string(SINEW_TEST_DATA_DIR) + "/projectchrono/chrono/data/opensim/Rajagopal2015.osim");
  spec.forces.clear();
  sinew::engine::System system(spec.gravity);
  sinew::opensim::OpenSimParser parser;
  parser.ParseSpec(system, spec);
  system.Finalize();
  TimeOneSecond(bench, system, "euler");
}
BENCHMARK(BM_SkeletonFallingWithoutCollisionStep)->Unit(benchmark::kMillisecond);

}  // namespace

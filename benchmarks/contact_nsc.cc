// The NSC contact method on the skeleton-on-ground scene (issue 14's figure): the seed's
// Rajagopal2015 with its collision cylinders, dropped 5 cm onto a ground plane, h = 1e-3 s,
// the seed's default material (friction 0.6, no restitution), default solver settings (100
// iterations at most, tolerance 1e-6 m/s) with either impulse solver: apgd:0 Gauss-Seidel,
// apgd:1 APGD (the default). Counters: sweeps (Gauss-Seidel sweeps or APGD iterations), products
// (W x), residual (mean and largest of the steps', m/s).
//  - BM_Rajagopal2015NscDropOneSecond: the first simulated second (fall, impact, settling);
//    reports us per step and the mean number of contacts.
//  - BM_Rajagopal2015NscRestingStep: one step of the skeleton lying on the ground after 2 s
//    (the steady state: every step with contacts), reached with the default solver for both
//    (so both solve the same scene), then 50 untimed steps of the measured solver. Also reports
//    the largest body speed and spin over the timed steps (max_speed m/s, max_spin rad/s): whether
//    the skeleton is at rest in them (the timed steps go on from 2.05 s, one per iteration).
#include <benchmark/benchmark.h>
#include <sinew/engine/nsc_integrator.h>

#include <algorithm>

#include "contact/skeleton_on_ground.h"

namespace {

sinew::engine::NscSettings Solver(const benchmark::State& bench) {
  sinew::engine::NscSettings nsc;
  nsc.solver.method = bench.range(0) == 1 ? sinew::engine::ContactSolverMethod::kApgd
                                          : sinew::engine::ContactSolverMethod::kGaussSeidel;
  return nsc;
}

void BM_Rajagopal2015NscDropOneSecond(benchmark::State& bench) {
  double steps = 0.0, contacts = 0.0, sweeps = 0.0, products = 0.0, residual = 0.0, worst = 0.0;
  for (auto _ : bench) {
    bench.PauseTiming();
    sinew::testing::SkeletonOnGround scene = sinew::testing::MakeSkeletonOnGround(0.05);
    sinew::engine::IntegratorSettings settings;
    settings.step = 1e-3;
    sinew::engine::NscIntegrator integrator(*scene.system, scene.provider, settings, Solver(bench));
    bench.ResumeTiming();
    for (int n = 1; n <= 1000; ++n) {
      integrator.StepTo(scene.state, n * 1e-3);
      contacts += integrator.last_step().contacts;
      sweeps += integrator.last_step().iterations;
      products += integrator.last_step().products;
      residual += integrator.last_step().residual;
      worst = std::max(worst, integrator.last_step().residual);
    }
    steps += 1000;
  }
  bench.counters["us_per_step"] =
      benchmark::Counter(steps * 1e-6, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  bench.counters["contacts"] = benchmark::Counter(contacts / steps);
  bench.counters["sweeps"] = benchmark::Counter(sweeps / steps);
  bench.counters["products"] = benchmark::Counter(products / steps);
  bench.counters["residual"] = benchmark::Counter(residual / steps);
  bench.counters["worst_residual"] = benchmark::Counter(worst);
}
BENCHMARK(BM_Rajagopal2015NscDropOneSecond)
    ->ArgName("apgd")
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond);

void BM_Rajagopal2015NscRestingStep(benchmark::State& bench) {
  sinew::testing::SkeletonOnGround scene = sinew::testing::MakeSkeletonOnGround(0.05);
  sinew::engine::IntegratorSettings settings;
  settings.step = 1e-3;
  {
    // Both solvers from the same resting state: settled by the default solver, then 50 steps
    // of the measured one (to warm-start it) before the timing.
    sinew::engine::NscIntegrator settle(*scene.system, scene.provider, settings);
    settle.StepTo(scene.state, 2.0);
  }
  sinew::engine::NscIntegrator integrator(*scene.system, scene.provider, settings, Solver(bench));
  integrator.StepTo(scene.state, 2.05);
  double contacts = 0.0, sweeps = 0.0, products = 0.0, residual = 0.0, worst = 0.0, steps = 0.0;
  double max_speed = 0.0, max_spin = 0.0;
  for (auto _ : bench) {
    integrator.Advance(scene.state, scene.state.t + 1e-3);
    for (const sinew::engine::BodyState& b : scene.state.bodies) {
      max_speed = std::max(max_speed, b.v_GB.norm());
      max_spin = std::max(max_spin, b.w_GB.norm());
    }
    contacts += integrator.last_step().contacts;
    sweeps += integrator.last_step().iterations;
    products += integrator.last_step().products;
    residual += integrator.last_step().residual;
    worst = std::max(worst, integrator.last_step().residual);
    steps += 1.0;
  }
  bench.counters["contacts"] = benchmark::Counter(contacts / steps);
  bench.counters["sweeps"] = benchmark::Counter(sweeps / steps);
  bench.counters["products"] = benchmark::Counter(products / steps);
  bench.counters["residual"] = benchmark::Counter(residual / steps);
  bench.counters["worst_residual"] = benchmark::Counter(worst);
  bench.counters["max_speed"] = benchmark::Counter(max_speed);
  bench.counters["max_spin"] = benchmark::Counter(max_spin);
}
BENCHMARK(BM_Rajagopal2015NscRestingStep)
    ->ArgName("apgd")
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMicrosecond);

}  // namespace

// One simulated second of Rajagopal2016 with its 80 Millard2012EquilibriumMuscles (some with
// rigid tendons) on their wrapped paths, RK45 at accuracy 1e-5. The pelvis's six coordinates are
// locked, so the legs and trunk swing from a fixed pelvis instead of the model falling through
// the floor it has no contact with. No controls: the excitations are 0 and the activations decay
// from their defaults. Fibers start at equilibrium. Reports simulated seconds per CPU second.
#include <benchmark/benchmark.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/integrator.h>
#include <sinew/io/osim_reader.h>
#include <sinew/opensim/parser.h>

#include <memory>
#include <string>

namespace {

void BM_Rajagopal2016MillardOneSecond(benchmark::State& bench) {
  sinew::model::ModelSpec spec =
      sinew::io::ReadOsim(std::string(SINEW_TEST_DATA_DIR) +
                          "/opensim-org/opensim-models/Models/Rajagopal/Rajagopal2016.osim");
  for (sinew::model::CoordinateSpec& c : spec.coordinates) {
    if (c.name.starts_with("pelvis_")) c.locked = true;
  }
  sinew::OpenSimParser parser;
  parser.EquilibrateMuscles(true);
  sinew::engine::System system(spec.gravity);
  parser.ParseSpec(system, spec);
  system.Finalize();
  const sinew::engine::State start = sinew::engine::MakeDefaultState(system);
  double simulated = 0.0, steps = 0.0, evaluations = 0.0;
  for (auto _ : bench) {
    sinew::engine::State state = start;
    auto integrator = sinew::engine::MakeIntegrator("rk45", system, {.accuracy = 1e-5});
    integrator->SetController(parser.GetController());
    integrator->StepTo(state, 1.0);
    simulated += 1.0;
    steps += static_cast<double>(integrator->stats().steps);
    evaluations += static_cast<double>(integrator->stats().evaluations);
  }
  bench.counters["sim_s_per_s"] = benchmark::Counter(simulated, benchmark::Counter::kIsRate);
  bench.counters["steps"] = benchmark::Counter(steps, benchmark::Counter::kAvgIterations);
  bench.counters["evals"] = benchmark::Counter(evaluations, benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_Rajagopal2016MillardOneSecond)->Unit(benchmark::kMillisecond);

}  // namespace

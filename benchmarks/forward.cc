// OpenSim Forward setups through the library, as `sinew forward` runs them (setup read, force
// set files appended, states file row, controls and external loads, RK45 at the setup's
// integrator_error_tolerance and step bounds), output tables left out:
// - BM_PendulumSetup: pendulum_ext_gravity_Setup_Forward.xml, 1 s (a point mass on a pin held
//   by an external force);
// - BM_Subject01SetupWithoutMuscles: subject01_Setup_Forward.xml, 0.8 to 0.95 s, gait2354 with
//   CMC's 12 actuators, their controls and the ground reaction forces. Its 54 muscles are NOT
//   simulated yet (they are left out), so this is the cost of the skeleton, actuators and loads
//   of that run, not of OpenSim's muscle-driven one.
// Reports simulated seconds per wall second (sim_s_per_s) and the steps taken.
#include <benchmark/benchmark.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/integrator.h>
#include <sinew/io/forward_setup.h>
#include <sinew/io/osim_reader.h>
#include <sinew/io/storage.h>
#include <sinew/io/storage_labels.h>
#include <sinew/opensim/parser.h>

#include <string>

namespace {

const std::string kForward = std::string(SINEW_TEST_DATA_DIR) +
                             "/opensim-org/opensim-core/Applications/Forward/tests/resources/";

// The coordinates' defaults from the first row of the setup's states file (the row at its
// initial time in both setups here).
void UseFirstStatesRow(const std::string& file, sinew::model::ModelSpec& spec) {
  const sinew::io::Storage table = sinew::io::ReadStorage(file);
  for (sinew::model::CoordinateSpec& c : spec.coordinates) {
    using Kind = sinew::io::CoordinateColumnKind;
    const int value = sinew::io::FindCoordinateColumn(table, c.name, Kind::kValue);
    const int speed = sinew::io::FindCoordinateColumn(table, c.name, Kind::kSpeed);
    if (value >= 0) c.default_value = table.Value(0, value);
    if (speed >= 0) c.default_speed_value = table.Value(0, speed);
  }
}

void RunSetup(benchmark::State& bench, const std::string& setup_file) {
  const sinew::io::ForwardSetup setup = sinew::io::ReadForwardSetup(setup_file);
  sinew::model::ModelSpec spec =
      sinew::io::ReadOsim(setup.model_file, {setup.force_set_files, setup.replace_force_set});
  if (!setup.states_file.empty()) UseFirstStatesRow(setup.states_file, spec);
  sinew::OpenSimParser parser;
  parser.SetControlsFile(setup.controls_file);
  if (!setup.external_loads_file.empty()) parser.AddExternalLoads(setup.external_loads_file);
  auto system = std::make_unique<sinew::engine::System>();
  parser.ParseSpec(*system, spec);
  system->Finalize();
  sinew::engine::IntegratorSettings settings;
  settings.accuracy = setup.integrator_error_tolerance;
  settings.step = setup.maximum_integrator_step_size;
  settings.min_step = setup.minimum_integrator_step_size;
  double simulated = 0.0, steps = 0.0;
  for (auto _ : bench) {
    sinew::engine::State state = sinew::engine::MakeDefaultState(*system, setup.initial_time);
    auto integrator = sinew::engine::MakeIntegrator("rk45", *system, settings);
    integrator->SetController(parser.GetController());
    integrator->StepTo(state, setup.final_time);
    simulated += setup.final_time - setup.initial_time;
    steps += static_cast<double>(integrator->stats().steps);
  }
  bench.counters["sim_s_per_s"] = benchmark::Counter(simulated, benchmark::Counter::kIsRate);
  bench.counters["steps"] = benchmark::Counter(steps, benchmark::Counter::kAvgIterations);
}

void BM_PendulumSetup(benchmark::State& bench) {
  RunSetup(bench, kForward + "pendulum_ext_gravity_Setup_Forward.xml");
}
BENCHMARK(BM_PendulumSetup)->Unit(benchmark::kMillisecond);

void BM_Subject01SetupWithoutMuscles(benchmark::State& bench) {
  RunSetup(bench, kForward + "subject01_Setup_Forward.xml");
}
BENCHMARK(BM_Subject01SetupWithoutMuscles)->Unit(benchmark::kMillisecond);

}  // namespace

// One simulated second of Rajagopal2016 with its 80 Millard2012EquilibriumMuscles (some with
// rigid tendons) on their wrapped paths, rk45, cvode and cvode-gmres at accuracy 1e-5. The
// pelvis's six coordinates are locked, so the legs and trunk swing from a fixed pelvis instead
// of the model falling through the floor it has no contact with. Fibers start at equilibrium.
// No controls (the excitations are 0 and the activations decay from their defaults), or, in the
// Excited benchmarks, every excitation held at 0.2. Reports simulated seconds per CPU second.
#include <benchmark/benchmark.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/integrator.h>
#include <sinew/functions/constant.h>
#include <sinew/io/osim_reader.h>
#include <sinew/opensim/parser.h>

#include <memory>
#include <string>

#include "one_second_run.h"

namespace {

// `excitation` >= 0: every muscle's excitation held at that constant (otherwise no controls).
void RunRajagopal(benchmark::State& bench, const std::string& integrator,
                  double excitation = -1.0) {
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
  if (excitation >= 0.0) {
    for (const sinew::model::ForceSpec& force : spec.forces) {
      if (force.type != "Millard2012EquilibriumMuscle") continue;
      parser.SetExcitationFunction(force.name,
                                   std::make_shared<sinew::functions::Constant>(excitation));
    }
  }
  const sinew::engine::State start = sinew::engine::MakeDefaultState(system);
  RunOneSecond(bench, system, parser.GetController(), start, 1e-5, integrator);
}

void BM_Rajagopal2016MillardOneSecond(benchmark::State& bench) { RunRajagopal(bench, "rk45"); }
void BM_Rajagopal2016MillardOneSecondCvode(benchmark::State& bench) {
  RunRajagopal(bench, "cvode");
}
// Every muscle excited at 0.2: activations rise from their defaults and the muscles pull.
void BM_Rajagopal2016MillardExcitedOneSecond(benchmark::State& bench) {
  RunRajagopal(bench, "rk45", 0.2);
}
void BM_Rajagopal2016MillardExcitedOneSecondCvodeGmres(benchmark::State& bench) {
  RunRajagopal(bench, "cvode-gmres", 0.2);
}
void BM_Rajagopal2016MillardExcitedOneSecondCvodeGmresBd(benchmark::State& bench) {
  RunRajagopal(bench, "cvode-gmres-bd", 0.2);
}
void BM_Rajagopal2016MillardOneSecondCvodeGmres(benchmark::State& bench) {
  RunRajagopal(bench, "cvode-gmres");
}
void BM_Rajagopal2016MillardOneSecondCvodeGmresBd(benchmark::State& bench) {
  RunRajagopal(bench, "cvode-gmres-bd");
}
BENCHMARK(BM_Rajagopal2016MillardOneSecond)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Rajagopal2016MillardOneSecondCvode)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Rajagopal2016MillardOneSecondCvodeGmres)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Rajagopal2016MillardOneSecondCvodeGmresBd)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Rajagopal2016MillardExcitedOneSecond)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Rajagopal2016MillardExcitedOneSecondCvodeGmres)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Rajagopal2016MillardExcitedOneSecondCvodeGmresBd)->Unit(benchmark::kMillisecond);

}  // namespace

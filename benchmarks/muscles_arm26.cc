// One simulated second of OpenSim's arm26 forward test (tests/muscles/arm26_forward_test.cc):
// 6 muscles (Thelen2003Muscle, and Thelen2003Muscle_Deprecated as OpenSim's test reads them)
// driven by arm26_StaticOptimization_controls.xml from arm26_InitialStates.sto, rk45 (and, for
// Thelen2003Muscle, cvode and cvode-gmres) at accuracy 1e-5 (OpenSim's
// integrator_error_tolerance in the setup) and 1e-7, the paths wrapped over arm26's cylinders
// and ellipsoids. Reports simulated seconds per wall second.
#include <benchmark/benchmark.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/integrator.h>
#include <sinew/io/osim_reader.h>
#include <sinew/io/storage.h>
#include <sinew/opensim/parser.h>
#include <sinew/opensim/states_table.h>

#include <memory>
#include <string>

#include "one_second_run.h"

namespace {

const std::string kDir = std::string(SINEW_TEST_DATA_DIR) +
                         "/opensim-org/opensim-core/Applications/Forward/tests/resources/";

void RunArm26(benchmark::State& bench, bool deprecated, double accuracy,
              const std::string& integrator = "rk45") {
  sinew::model::ModelSpec spec = sinew::io::ReadOsim(kDir + "arm26.osim");
  const sinew::io::Storage initial = sinew::io::ReadStorage(kDir + "arm26_InitialStates.sto");
  for (sinew::model::CoordinateSpec& c : spec.coordinates) {
    c.default_value = initial.Value(0, initial.FindColumn(c.name));
    c.default_speed_value = initial.Value(0, initial.FindColumn(c.name + "_u"));
  }
  sinew::OpenSimParser parser;
  if (deprecated) parser.RenameForceClass("Thelen2003Muscle", "Thelen2003Muscle_Deprecated");
  parser.SetControlsFile(kDir + "arm26_StaticOptimization_controls.xml");
  sinew::engine::System system(spec.gravity);
  parser.ParseSpec(system, spec);
  system.Finalize();
  sinew::engine::State start = sinew::engine::MakeDefaultState(system);
  for (size_t i = 0; i < initial.labels.size(); ++i) {
    const int z = sinew::opensim::FindStateVariableColumn(system, initial.labels[i]);
    if (z >= 0) start.z[z] = initial.Value(0, static_cast<int>(i));
  }
  RunOneSecond(bench, system, parser.GetController(), start, accuracy, integrator);
}

void BM_Arm26Thelen2003(benchmark::State& bench) { RunArm26(bench, false, bench.range(0) * 1e-7); }
void BM_Arm26Thelen2003Deprecated(benchmark::State& bench) {
  RunArm26(bench, true, bench.range(0) * 1e-7);
}
void BM_Arm26Thelen2003Cvode(benchmark::State& bench) {
  RunArm26(bench, false, bench.range(0) * 1e-7, "cvode");
}
void BM_Arm26Thelen2003CvodeGmres(benchmark::State& bench) {
  RunArm26(bench, false, bench.range(0) * 1e-7, "cvode-gmres");
}
void BM_Arm26Thelen2003CvodeGmresBd(benchmark::State& bench) {
  RunArm26(bench, false, bench.range(0) * 1e-7, "cvode-gmres-bd");
}
// range(0) * 1e-7 is the accuracy: 100 -> 1e-5, 1 -> 1e-7.
BENCHMARK(BM_Arm26Thelen2003)->Arg(100)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Arm26Thelen2003Deprecated)->Arg(100)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Arm26Thelen2003Cvode)->Arg(100)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Arm26Thelen2003CvodeGmres)->Arg(100)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Arm26Thelen2003CvodeGmresBd)->Arg(100)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace

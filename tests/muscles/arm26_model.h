// arm26 as OpenSim's Forward tool runs it in its own test (Applications/Forward/tests/
// testForward.cpp, testArm26), shared by the muscle tests that simulate it.
#pragma once

#include <gtest/gtest.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/simulation.h>
#include <sinew/engine/system.h>
#include <sinew/io/osim_reader.h>
#include <sinew/io/storage.h>
#include <sinew/opensim/parser.h>
#include <sinew/opensim/states_table.h>
#include <sinew/paths/geometry_path.h>

#include <algorithm>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace sinew::muscles {

inline const std::string kArm26Dir =
    std::string(SINEW_TEST_DATA_DIR) +
    "/opensim-org/opensim-core/Applications/Forward/tests/resources/";

struct Arm26 {
  model::ModelSpec spec;
  opensim::OpenSimParser parser;
  std::unique_ptr<engine::System> system;
  engine::State state;
};

// The model, its controls and the initial states file's first row (coordinates and the
// muscles' activation and fiber_length), as the Forward tool sets them, its cylinders following
// `refinement` (by default OpenSim 2.x's rule, with which std_arm26_states.sto was written).
// `controls` and `initial_states` default to the Forward test's files. `equilibrate`: the
// fiber lengths are then the muscles' equilibrium at that pose and activation instead
// (the Forward tool's solve_for_equilibrium_for_auxiliary_states).
inline std::unique_ptr<Arm26> LoadArm26(
    paths::CylinderRefinement refinement = paths::CylinderRefinement::kAlways,
    const std::string& controls = kArm26Dir + "arm26_StaticOptimization_controls.xml",
    const std::string& initial_states = kArm26Dir + "arm26_InitialStates.sto",
    bool equilibrate = false) {
  auto arm = std::make_unique<Arm26>();
  arm->spec = io::ReadOsim(kArm26Dir + "arm26.osim");
  const io::Storage initial = io::ReadStorage(initial_states);
  for (model::CoordinateSpec& c : arm->spec.coordinates) {
    c.default_value = initial.Value(0, initial.FindColumn(c.name));
    c.default_speed_value = initial.Value(0, initial.FindColumn(c.name + "_u"));
  }
  arm->parser.RenameForceClass("Thelen2003Muscle", "Thelen2003Muscle_Deprecated");
  arm->parser.SetControlsFile(controls);
  arm->parser.SetCylinderRefinement(refinement);
  arm->parser.EquilibrateMuscles(equilibrate);
  arm->system = std::make_unique<engine::System>(arm->spec.gravity);
  arm->parser.ParseSpec(*arm->system, arm->spec);
  arm->system->Finalize();
  arm->state = engine::MakeDefaultState(*arm->system);
  int set = 0;
  for (size_t i = 0; i < initial.labels.size(); ++i) {
    const int z = opensim::FindStateVariableColumn(*arm->system, initial.labels[i]);
    if (z < 0) continue;
    arm->state.z[z] = initial.Value(0, static_cast<int>(i));
    ++set;
  }
  EXPECT_EQ(set, 12);
  if (equilibrate) engine::InitializeStateVariables(*arm->system, arm->state);
  return arm;
}

// The reference's value of column `label` at time t, by linear interpolation between rows.
inline double ReferenceAt(const io::Storage& reference, const std::string& label, double t) {
  const int c = reference.FindColumn(label);
  EXPECT_GE(c, 0) << label;
  const auto it = std::lower_bound(reference.time.begin(), reference.time.end(), t);
  const int i =
      std::clamp(static_cast<int>(it - reference.time.begin()), 1, reference.NumRows() - 1);
  const double w = (t - reference.time[i - 1]) / (reference.time[i] - reference.time[i - 1]);
  return (1 - w) * reference.Value(i - 1, c) + w * reference.Value(i, c);
}

// OpenSim 2.x's label of a state: "/jointset/r_elbow/r_elbow_flex/value" -> "r_elbow_flex",
// ".../speed" -> "r_elbow_flex_u", "/forceset/BRA/activation" -> "BRA.activation".
inline std::string OpenSim2StateLabel(std::string label) {
  if (label.starts_with("/jointset/")) {
    const size_t last = label.rfind('/'), before = label.rfind('/', last - 1);
    const std::string name = label.substr(before + 1, last - before - 1);
    return label.ends_with("/speed") ? name + "_u" : name;
  }
  label = label.substr(std::string("/forceset/").size());
  label[label.find('/')] = '.';
  return label;
}

// Simulates `arm` for 1 s with rk45 at `accuracy`, and at every `interval` calls
// visit(t, label, value, reference value) for each state, the reference interpolated at t.
inline void CompareWithReference(
    Arm26& arm, const io::Storage& reference, double accuracy, double interval,
    const std::function<void(double, const std::string&, double, double)>& visit) {
  auto integrator = engine::MakeIntegrator("rk45", *arm.system, {.accuracy = accuracy});
  integrator->SetController(arm.parser.GetController());
  std::vector<std::string> labels = opensim::StatesLabels(*arm.system);
  for (std::string& label : labels) label = OpenSim2StateLabel(label);
  std::vector<double> row;
  engine::SimulationOptions run;
  run.duration = 1.0;
  run.report_interval = interval;
  engine::Simulate(*integrator, arm.state, run, [&](const engine::State& state) {
    opensim::StatesRow(*arm.system, state, row);
    for (size_t i = 0; i < labels.size(); ++i) {
      visit(state.t, labels[i], row[i], ReferenceAt(reference, labels[i], state.t));
    }
  });
}

}  // namespace sinew::muscles

// arm26 as OpenSim's Forward tool runs it in its own test (Applications/Forward/tests/
// testForward.cpp, testArm26), shared by the muscle tests that simulate it.
#pragma once

#include <gtest/gtest.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/system.h>
#include <sinew/io/osim_reader.h>
#include <sinew/io/storage.h>
#include <sinew/opensim/parser.h>
#include <sinew/opensim/states_table.h>
#include <sinew/paths/geometry_path.h>

#include <memory>
#include <string>

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
inline std::unique_ptr<Arm26> LoadArm26(
    paths::CylinderRefinement refinement = paths::CylinderRefinement::kAlways) {
  auto arm = std::make_unique<Arm26>();
  arm->spec = io::ReadOsim(kArm26Dir + "arm26.osim");
  const io::Storage initial = io::ReadStorage(kArm26Dir + "arm26_InitialStates.sto");
  for (model::CoordinateSpec& c : arm->spec.coordinates) {
    c.default_value = initial.Value(0, initial.FindColumn(c.name));
    c.default_speed_value = initial.Value(0, initial.FindColumn(c.name + "_u"));
  }
  arm->parser.RenameForceClass("Thelen2003Muscle", "Thelen2003Muscle_Deprecated");
  arm->parser.SetControlsFile(kArm26Dir + "arm26_StaticOptimization_controls.xml");
  arm->parser.SetCylinderRefinement(refinement);
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
  return arm;
}

}  // namespace sinew::muscles

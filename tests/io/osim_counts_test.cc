// Counts of bodies, joints, coordinates, forces, constraints and markers read from 15 real files
// (format 1.9 to 4.6, 3.x and 4.x layouts, chrono seed models, Rajagopal2016, Hamner, gait2354,
// arm26, a ScapulothoracicJoint model, bouncing_block with '::', lenhart2015 with a bare '&'),
// checked against numbers counted INDEPENDENTLY with tests/io/count_osim.py: Python's
// xml.etree parser (not pugixml, not Sinew), see its docstring for the counting rules. Rerun:
//   python3 tests/io/count_osim.py $(find tests/data/osim -name '*.osim' | sort)
#include <gtest/gtest.h>

#include <string>

#include "io/osim_reader.h"

namespace sinew {
namespace {

struct Expected {
  const char* file;
  int version, bodies, joints, coordinates, forces, constraints, markers;
};

// Output of count_osim.py, unchanged.
constexpr Expected kExpected[] = {
    {"osim/clnsmith/opensim-jam/models/lenhart2015/scale_generic_model/lenhart2015_unscaled.osim",
     40000, 25, 25, 52, 134, 0, 0},
    {"osim/opensim-org/opensim-core/OpenSim/Simulation/SimbodyEngine/Test/"
     "double_pendulum_testReverse.osim",
     20302, 2, 2, 2, 0, 0, 0},
    {"osim/opensim-org/opensim-core/OpenSim/Simulation/Test/BouncingBall_HuntCrossley.osim", 20001,
     1, 1, 6, 1, 0, 0},
    {"osim/opensim-org/opensim-core/OpenSim/Simulation/Test/StationDefinedFrames_Advanced.osim",
     40600, 2, 2, 12, 0, 0, 0},
    {"osim/opensim-org/opensim-core/OpenSim/Simulation/Test/arm26.osim", 10901, 2, 2, 2, 6, 0, 3},
    {"osim/opensim-org/opensim-core/OpenSim/Simulation/Test/double_pendulum.osim", 30501, 2, 2, 2,
     0, 0, 0},
    {"osim/opensim-org/opensim-core/OpenSim/Simulation/Test/gait2354_simbody.osim", 10905, 12, 12,
     23, 54, 0, 0},
    {"osim/opensim-org/opensim-core/OpenSim/Simulation/Test/"
     "testSimulationUtilities_leg6dof9musc_20303.osim",
     20303, 7, 7, 7, 9, 1, 12},
    {"osim/opensim-org/opensim-core/OpenSim/Tools/Test/BuiltinGeometry.osim", 30517, 1, 1, 6, 3, 1,
     0},
    {"osim/opensim-org/opensim-models/Models/Arm26/arm26.osim", 40000, 3, 3, 2, 6, 0, 3},
    {"osim/opensim-org/opensim-models/Models/BouncingBlock/bouncing_block.osim", 40000, 3, 3, 8, 4,
     2, 0},
    {"osim/opensim-org/opensim-models/Models/Hamner/FullBodyModel_Hamner2010_v2_0.osim", 40000, 20,
     20, 37, 92, 0, 83},
    {"osim/opensim-org/opensim-models/Models/Rajagopal/Rajagopal2016.osim", 40000, 22, 22, 39, 97,
     2, 66},
    {"osim/projectchrono/chrono/data/opensim/ScapulothorachicJoint_Shoulder.osim", 30000, 7, 7, 17,
     5, 1, 21},
    {"osim/projectchrono/chrono/data/opensim/newton_cradle.osim", 30000, 5, 5, 15, 2, 0, 0},
};

class OsimCounts : public ::testing::TestWithParam<Expected> {};

TEST_P(OsimCounts, MatchIndependentCount) {
  const Expected& e = GetParam();
  const ModelSpec spec = ReadOsim(std::string(SINEW_TEST_DATA_DIR) + "/" + e.file);
  EXPECT_EQ(spec.version, e.version);
  EXPECT_EQ(static_cast<int>(spec.bodies.size()) - 1, e.bodies);  // ground is bodies[0]
  EXPECT_EQ(static_cast<int>(spec.joints.size()), e.joints);
  EXPECT_EQ(static_cast<int>(spec.coordinates.size()), e.coordinates);
  EXPECT_EQ(static_cast<int>(spec.forces.size()), e.forces);
  EXPECT_EQ(static_cast<int>(spec.constraints.size()), e.constraints);
  EXPECT_EQ(static_cast<int>(spec.markers.size()), e.markers);
  // Every joint's coordinates belong to it, and every coordinate to exactly one joint.
  int listed = 0;
  for (size_t j = 0; j < spec.joints.size(); ++j) {
    for (int c : spec.joints[j].coordinates) {
      EXPECT_EQ(spec.coordinates[c].joint, static_cast<int>(j));
      ++listed;
    }
  }
  EXPECT_EQ(listed, static_cast<int>(spec.coordinates.size()));
}

std::string TestName(const ::testing::TestParamInfo<Expected>& info) {
  std::string name = info.param.file;
  name = name.substr(name.rfind('/') + 1);
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name + "_" + std::to_string(info.index);
}

INSTANTIATE_TEST_SUITE_P(RealFiles, OsimCounts, ::testing::ValuesIn(kExpected), TestName);

}  // namespace
}  // namespace sinew

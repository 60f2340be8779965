// Counts of bodies, joints, coordinates, forces, constraints and markers read from 15 real files
// (format 1.9 to 4.6, 3.x and 4.x layouts, chrono seed models, Rajagopal2016, Hamner, gait2354,
// arm26, a ScapulothoracicJoint model, bouncing_block with '::', lenhart2015 with a bare '&'),
// checked against numbers counted INDEPENDENTLY with tests/io/count_osim.py: Python's
// xml.etree parser (not pugixml, not Sinew), see its docstring for the counting rules. Rerun:
// The 15 files are those named in tests/data/sinew/joint_bodies.txt; from tests/data, with
// FILES=$(awk '{print $1}' sinew/joint_bodies.txt | sort -u):
//   python3 ../io/count_osim.py $FILES
//   python3 ../io/count_osim.py --joints $FILES   (output saved as sinew/joint_bodies.txt)
//   python3 ../io/count_osim.py --frames $FILES   (output saved as sinew/joint_frames.txt)
#include <gtest/gtest.h>
#include <sinew/io/osim_reader.h>

#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace sinew {
namespace {

struct Expected {
  const char* file;
  int version, bodies, joints, coordinates, forces, constraints, markers;
};

// Output of count_osim.py, unchanged.
constexpr Expected kExpected[] = {
    {"clnsmith/opensim-jam/models/lenhart2015/scale_generic_model/lenhart2015_unscaled.osim", 40000,
     25, 25, 52, 134, 0, 0},
    {"opensim-org/opensim-core/OpenSim/Simulation/SimbodyEngine/Test/"
     "double_pendulum_testReverse.osim",
     20302, 2, 2, 2, 0, 0, 0},
    {"opensim-org/opensim-core/OpenSim/Simulation/Test/BouncingBall_HuntCrossley.osim", 20001, 1, 1,
     6, 1, 0, 0},
    {"opensim-org/opensim-core/OpenSim/Simulation/Test/StationDefinedFrames_Advanced.osim", 40600,
     2, 2, 12, 0, 0, 0},
    {"opensim-org/opensim-core/OpenSim/Simulation/Test/arm26.osim", 10901, 2, 2, 2, 6, 0, 3},
    {"opensim-org/opensim-core/OpenSim/Simulation/Test/double_pendulum.osim", 30501, 2, 2, 2, 0, 0,
     0},
    {"opensim-org/opensim-core/OpenSim/Simulation/Test/gait2354_simbody.osim", 10905, 12, 12, 23,
     54, 0, 0},
    {"opensim-org/opensim-core/OpenSim/Simulation/Test/"
     "testSimulationUtilities_leg6dof9musc_20303.osim",
     20303, 7, 7, 7, 9, 1, 12},
    {"opensim-org/opensim-core/OpenSim/Tools/Test/BuiltinGeometry.osim", 30517, 1, 1, 6, 3, 1, 0},
    {"opensim-org/opensim-models/Models/Arm26/arm26.osim", 40000, 3, 3, 2, 6, 0, 3},
    {"opensim-org/opensim-models/Models/BouncingBlock/bouncing_block.osim", 40000, 3, 3, 8, 4, 2,
     0},
    {"opensim-org/opensim-models/Models/Hamner/FullBodyModel_Hamner2010_v2_0.osim", 40000, 20, 20,
     37, 92, 0, 83},
    {"opensim-org/opensim-models/Models/Rajagopal/Rajagopal2016.osim", 40000, 22, 22, 39, 97, 2,
     66},
    {"projectchrono/chrono/data/opensim/ScapulothorachicJoint_Shoulder.osim", 30000, 7, 7, 17, 5, 1,
     21},
    {"projectchrono/chrono/data/opensim/newton_cradle.osim", 30000, 5, 5, 15, 2, 0, 0},
};

class OsimCounts : public ::testing::TestWithParam<Expected> {};

TEST_P(OsimCounts, MatchIndependentCount) {
  const Expected& e = GetParam();
  const model::ModelSpec spec = io::ReadOsim(std::string(SINEW_TEST_DATA_DIR) + "/" + e.file);
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

// Every joint's parent and child body in the same 15 files, against
// tests/data/sinew/joint_bodies.txt, written by `count_osim.py --joints` (its own resolution of
// socket paths, offset frames, station-defined frames, 3.05 connectors, 3.x nesting and reverse).
TEST(OsimJointBodies, MatchIndependentResolution) {
  std::ifstream in(std::string(SINEW_TEST_DATA_DIR) + "/sinew/joint_bodies.txt");
  ASSERT_TRUE(in.good());
  struct Row {
    std::string joint, parent, child;
  };
  std::map<std::string, std::vector<Row>> by_file;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string file;
    Row row;
    fields >> file >> row.joint >> row.parent >> row.child;
    by_file[file].push_back(row);
  }
  ASSERT_EQ(by_file.size(), std::size(kExpected));
  int compared = 0;
  for (const auto& [file, rows] : by_file) {
    const model::ModelSpec spec = io::ReadOsim(std::string(SINEW_TEST_DATA_DIR) + "/" + file);
    ASSERT_EQ(spec.joints.size(), rows.size()) << file;
    for (size_t i = 0; i < rows.size(); ++i) {
      const model::JointSpec& j = spec.joints[i];
      if (rows[i].joint != "-") {  // "-": an unnamed 3.x joint
        EXPECT_EQ(j.name, rows[i].joint) << file;
      }
      EXPECT_EQ(spec.bodies[j.parent_body].name, rows[i].parent) << file << " " << j.name;
      EXPECT_EQ(spec.bodies[j.child_body].name, rows[i].child) << file << " " << j.name;
      ++compared;
    }
  }
  EXPECT_EQ(compared, 114);
}

// Every joint's X_PF and X_BM (frames resolved into the parent and child bodies) in the same
// files against tests/data/sinew/joint_frames.txt, computed by `count_osim.py --frames` with its
// own rotation and transform code. Joints on station-defined frames are not in that file.
// Tolerance 1e-12: a few products of rotations of O(1) numbers, done in a different order.
TEST(OsimJointFrames, MatchIndependentComputation) {
  std::ifstream in(std::string(SINEW_TEST_DATA_DIR) + "/sinew/joint_frames.txt");
  ASSERT_TRUE(in.good());
  // (file, joint name, occurrence) -> 24 numbers.
  std::map<std::string, std::map<std::string, std::vector<std::vector<double>>>> expected;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string file, joint;
    fields >> file >> joint;
    std::vector<double> numbers(24);
    for (double& x : numbers) fields >> x;
    ASSERT_FALSE(fields.fail()) << line;
    expected[file][joint].push_back(numbers);
  }
  int compared = 0;
  for (const auto& [file, joints] : expected) {
    const model::ModelSpec spec = io::ReadOsim(std::string(SINEW_TEST_DATA_DIR) + "/" + file);
    std::map<std::string, size_t> seen;
    for (const model::JointSpec& j : spec.joints) {
      const std::string key = j.element.name.empty() ? "-" : j.name;
      const auto it = joints.find(key);
      if (it == joints.end()) continue;  // on a station-defined frame
      const size_t k = seen[key]++;
      ASSERT_LT(k, it->second.size()) << file << " " << key;
      const std::vector<double>& e = it->second[k];
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) {
          EXPECT_NEAR(j.X_PF.R(r, c), e[3 * r + c], 1e-12) << file << " " << j.name;
          EXPECT_NEAR(j.X_BM.R(r, c), e[12 + 3 * r + c], 1e-12) << file << " " << j.name;
        }
        EXPECT_NEAR(j.X_PF.p(r), e[9 + r], 1e-12) << file << " " << j.name;
        EXPECT_NEAR(j.X_BM.p(r), e[21 + r], 1e-12) << file << " " << j.name;
      }
      ++compared;
    }
  }
  EXPECT_EQ(compared, 113);
}

}  // namespace
}  // namespace sinew

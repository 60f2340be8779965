// `sinew kinematics` end to end: files in OpenSim's layouts that match OpenSim's results,
// the default pose, unknown motion columns reported, bad input -> exit code 2 with file:line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "apps/cli_test_util.h"
#include "kinematics/sto_table.h"

namespace {

namespace fs = std::filesystem;
using sinew::testing::ReadStoTable;
using sinew::testing::StoTable;

const std::string kData =
    std::string(SINEW_TEST_DATA_DIR) + "/opensim-org/opensim-models/Pipelines/";
const std::string kChrono =
    std::string(SINEW_TEST_DATA_DIR) + "/projectchrono/chrono/data/opensim/";

using sinew::testing::CliRun;

class KinematicsCliTest : public sinew::testing::CliTest {
 protected:
  // `sinew kinematics ARGS`.
  CliRun Kinematics(const std::string& args) const { return Run("kinematics " + args); }
};

TEST_F(KinematicsCliTest, Gait2354BodiesMatchOpenSimBodyKinematics) {
  const fs::path& folder = dir();
  const CliRun r = Kinematics(
      kData + "Gait2354_Simbody/OutputReference/subject01_simbody_adjusted.osim --motion " + kData +
      "Gait2354_Simbody/OutputReference/ResultsForward/subject01_walk1_Kinematics_q.sto --out " +
      (folder / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const StoTable ours = ReadStoTable((folder / "out/bodies.sto").string());
  const StoTable ref = ReadStoTable(kData +
                                    "Gait2354_Simbody/OutputReference/ResultsForward/"
                                    "subject01_walk1_BodyKinematics_pos_global.sto");
  ASSERT_EQ(ours.rows.size(), ref.rows.size());
  ASSERT_EQ(ours.labels, ref.labels);  // same columns in the same order
  for (size_t row = 0; row < ref.rows.size(); ++row) {
    for (size_t c = 1; c < ref.labels.size(); ++c) {
      const std::string& l = ref.labels[c];
      if (l.rfind("torso_", 0) == 0 || l.rfind("center_of_mass", 0) == 0) continue;
      const bool angle = l.find("_O") != std::string::npos;
      double d = ours.rows[row][c] - ref.rows[row][c];
      if (angle) d = std::remainder(d, 360.0);
      EXPECT_LT(std::abs(d), angle ? 1e-5 : 1e-6) << l << " row " << row;
    }
  }
}

TEST_F(KinematicsCliTest, HamnerMarkersMatchOpenSimAndUnknownColumnsAreReported) {
  const fs::path& folder = dir();
  // The IK motion plus a column the model does not know.
  const StoTable motion =
      ReadStoTable(kData + "Hamner/outputReference/ResultsIK/subject02_running_ik.mot");
  {
    std::ofstream out(folder / "motion.mot");
    out.precision(17);
    out << "Coordinates\nversion=1\ninDegrees=yes\nendheader\n";
    for (const std::string& l : motion.labels) out << l << "\t";
    out << "not_a_coordinate\n";
    for (const auto& row : motion.rows) {
      for (double v : row) out << v << "\t";
      out << "1.0\n";
    }
  }
  const CliRun r =
      Kinematics(kData + "Hamner/outputReference/subject02_registered.osim --motion " +
                 (folder / "motion.mot").string() + " --out " + (folder / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("not_a_coordinate"), std::string::npos) << r.err;
  const StoTable ours = ReadStoTable((folder / "out/markers.sto").string());
  const StoTable ref =
      ReadStoTable(kData + "Hamner/outputReference/ResultsIK/ik_model_marker_locations.sto");
  ASSERT_EQ(ours.rows.size(), ref.rows.size());
  double max_error = 0.0;
  for (size_t c = 1; c < ref.labels.size(); ++c) {
    const int oc = ours.Column(ref.labels[c]);
    ASSERT_GE(oc, 0) << ref.labels[c];
    for (size_t row = 0; row < ref.rows.size(); ++row) {
      max_error = std::max(max_error, std::abs(ours.rows[row][oc] - ref.rows[row][c]));
    }
  }
  EXPECT_LT(max_error, 1e-6);
}

TEST_F(KinematicsCliTest, DefaultPoseWithoutMotion) {
  const fs::path& folder = dir();
  const CliRun r = Kinematics(kChrono + "double_pendulum.osim --out " + (folder / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const StoTable ours = ReadStoTable((folder / "out/bodies.sto").string());
  ASSERT_EQ(ours.rows.size(), 1u);
  // rod2's mass centre (its origin) by hand: two 0.5 m links at -45 and -105 degrees.
  const double q1 = -0.78539816, q12 = -0.78539816 - 1.04719755;
  EXPECT_NEAR(ours.rows[0][ours.Column("rod2_X")], 0.5 * std::sin(q1) + 0.5 * std::sin(q12), 1e-15);
  EXPECT_NEAR(ours.rows[0][ours.Column("rod2_Y")], -0.5 * std::cos(q1) - 0.5 * std::cos(q12),
              1e-15);
  EXPECT_NEAR(ours.rows[0][ours.Column("rod2_Oz")], q12 * 180 / std::numbers::pi, 1e-12);
}

TEST_F(KinematicsCliTest, BadInputGivesExitCode2WithFileAndLine) {
  const fs::path& folder = dir();
  CliRun r = Kinematics((folder / "missing.osim").string() + " --out " + (folder / "out").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("missing.osim"), std::string::npos) << r.err;
  {
    std::ofstream out(folder / "bad.mot");
    out << "Coordinates\nversion=1\ninDegrees=no\nendheader\ntime\tq1\n0.0\t0.1\n0.1\tabc\n";
  }
  r = Kinematics(kChrono + "double_pendulum.osim --motion " + (folder / "bad.mot").string() +
                 " --out " + (folder / "out").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("bad.mot:7"), std::string::npos) << r.err;
}

}  // namespace

// `sinew analyze` end to end: OpenSim MuscleAnalysis-style tables that match OpenSim's path
// lengths, moment arms that are the derivatives of the written lengths, wraps left out said
// loudly, and bad input -> exit code 2 naming what is wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "apps/cli_test_util.h"
#include "apps/unsupported_wraps.h"
#include "kinematics/sto_table.h"

namespace {

using sinew::testing::CliRun;
using sinew::testing::ReadStoTable;
using sinew::testing::StoTable;

const std::string kData = std::string(SINEW_TEST_DATA_DIR);
const std::string kGait1018 =
    kData + "/opensim-org/opensim-core/OpenSim/Moco/Test/walk_gait1018_subject01.osim";
const std::string kGait1018Motion =
    kData + "/opensim-org/opensim-core/OpenSim/Moco/Test/walk_gait1018_state_reference.mot";
const std::string kGait1018Lengths =
    kData +
    "/opensim-org/opensim-core/OpenSim/Tests/Wrapping/"
    "std_testGeometryPathWrapping_walk_gait1018_muscle_lengths.sto";
const std::string kArm26 = kData + "/MyoHub/myoconverter/models/osim/Arm26/arm26.osim";

class AnalyzeCliTest : public sinew::testing::CliTest {
 protected:
  CliRun Analyze(const std::string& args) const { return Run("analyze " + args); }
};

TEST_F(AnalyzeCliTest, Gait1018LengthsMatchOpenSimAndMomentArmsAreDerivatives) {
  const CliRun r = Analyze(kGait1018 + " --motion " + kGait1018Motion + " --out " + Path("out"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");  // every coordinate is in the motion, no path wraps
  const StoTable lengths = ReadStoTable(Path("out/Length.sto"));
  const StoTable reference = ReadStoTable(kGait1018Lengths);
  ASSERT_EQ(lengths.rows.size(), 151u);
  ASSERT_EQ(lengths.labels.size(), 19u);
  for (size_t c = 1; c < reference.labels.size(); ++c) {
    // OpenSim's labels are "/forceset/<muscle>|length"; ours are the muscle names.
    const std::string& label = reference.labels[c];
    const int ours = lengths.Column(label.substr(10, label.find('|') - 10));
    ASSERT_GE(ours, 0) << label;
    for (size_t row = 0; row < reference.rows.size(); ++row) {
      EXPECT_NEAR(lengths.rows[row][ours], reference.rows[row][c], 1e-6) << label;
    }
  }
  // One MomentArm file per free coordinate (all 10: none locked or coupled), and the
  // lengthening speeds.
  for (const char* coordinate :
       {"pelvis_tilt", "pelvis_tx", "pelvis_ty", "hip_flexion_r", "knee_angle_r", "ankle_angle_r",
        "hip_flexion_l", "knee_angle_l", "ankle_angle_l", "lumbar_extension"}) {
    EXPECT_TRUE(std::filesystem::exists(Path(std::string("out/MomentArm_") + coordinate + ".sto")))
        << coordinate;
  }
  const StoTable speeds = ReadStoTable(Path("out/LengtheningSpeed.sto"));
  ASSERT_EQ(speeds.rows.size(), 151u);
  // The lengthening speed integrates to the length change: the trapezoidal rule over the
  // 1/60 s frames is exact to its O(dt^2) error (measured 9.9e-5 m at worst over the 2.5 s).
  for (size_t c = 1; c < speeds.labels.size(); ++c) {
    double integral = 0.0;
    for (size_t row = 1; row < speeds.rows.size(); ++row) {
      integral += 0.5 * (speeds.rows[row][c] + speeds.rows[row - 1][c]) *
                  (speeds.rows[row][0] - speeds.rows[row - 1][0]);
    }
    EXPECT_NEAR(integral, lengths.rows.back()[c] - lengths.rows.front()[c], 3e-4)
        << speeds.labels[c];
  }
}

TEST_F(AnalyzeCliTest, CoordinatesOptionLimitsTheMomentArmFiles) {
  const CliRun r = Analyze(kGait1018 + " --motion " + kGait1018Motion + " --out " + Path("out") +
                           " --coordinates knee_angle_r,hip_flexion_l");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(Path("out"))) {
    files += entry.path().filename().string().rfind("MomentArm_", 0) == 0;
  }
  EXPECT_EQ(files, 2);
  // A right-leg muscle has no moment arm about the left hip; the left hamstrings do.
  const StoTable hip = ReadStoTable(Path("out/MomentArm_hip_flexion_l.sto"));
  const int vasti_r = hip.Column("vasti_r"), hamstrings_l = hip.Column("hamstrings_l");
  ASSERT_GE(vasti_r, 0);
  ASSERT_GE(hamstrings_l, 0);
  for (const std::vector<double>& row : hip.rows) {
    EXPECT_EQ(row[vasti_r], 0.0);
    EXPECT_GT(std::abs(row[hamstrings_l]), 0.01);  // centimetres, as a hip muscle's
  }
}

TEST_F(AnalyzeCliTest, WrapsNotAppliedAreNamedOnStderr) {
  const std::string motion = Path("arm.mot");
  {
    std::ofstream out(motion);
    out << "arm\nversion=1\nnRows=1\nnColumns=2\ninDegrees=yes\nendheader\n"
           "time\tr_elbow_flex\n0\t30\n";
  }
  // arm26 with its ellipsoids made WrapDoubleCylinderObst (a type Sinew does not wrap over).
  const CliRun r = Analyze(
      sinew::testing::WriteWithUnsupportedWraps(kArm26, Path("with_unsupported_wraps.osim")) +
      " --motion " + motion + " --out " + Path("out"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("sinew: warning: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("is not applied yet"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("/forceset/TRIlong"), std::string::npos) << r.err;
  // One row: too few for the speed spline, said once.
  EXPECT_NE(r.err.find("lengthening speeds are written as NaN"), std::string::npos) << r.err;
  EXPECT_TRUE(std::filesystem::exists(Path("out/Length.sto")));
}

TEST_F(AnalyzeCliTest, UnknownCoordinateIsAnErrorNamingIt) {
  const CliRun r = Analyze(kGait1018 + " --motion " + kGait1018Motion + " --out " + Path("out") +
                           " --coordinates knee_angle_x");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--coordinates: the model has no coordinate 'knee_angle_x'"),
            std::string::npos)
      << r.err;
}

TEST_F(AnalyzeCliTest, ModelWithoutPathsIsAnError) {
  const CliRun r = Analyze(kData +
                           "/opensim-org/opensim-core/OpenSim/Simulation/Test/"
                           "double_pendulum.osim --motion " +
                           kGait1018Motion + " --out " + Path("out"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("the model has no geometry path to analyze"), std::string::npos) << r.err;
}

}  // namespace

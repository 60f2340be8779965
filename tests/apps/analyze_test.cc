// `sinew analyze` end to end: OpenSim MuscleAnalysis-style tables that match OpenSim's path
// lengths, moment arms that are the derivatives of the written lengths, wraps left out said
// loudly, and bad input -> exit code 2 naming what is wrong.
#include <gtest/gtest.h>
#include <sinew/io/osim_reader.h>
#include <sinew/kinematics/coordinate_couplers.h>
#include <sinew/kinematics/kinematic_tree.h>
#include <sinew/paths/path_analysis.h>
#include <sinew/paths/path_set.h>

#include <Eigen/Dense>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

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
  // A one-row arm26 motion at shoulder elevation and elbow flexion (radians); its path.
  std::string WriteArmPose(double shoulder, double elbow) const {
    const std::string motion = Path("arm.mot");
    std::ofstream out(motion);
    out << "arm\nversion=1\nnRows=1\nnColumns=3\ninDegrees=no\nendheader\n"
           "time\tr_shoulder_elev\tr_elbow_flex\n0\t"
        << shoulder << "\t" << elbow << "\n";
    return motion;
  }
  // arm26's elbow moment arms at `motion` with `options` (e.g. a cylinder-refinement rule);
  // `name` keeps each call's output folder apart.
  StoTable ElbowMomentArms(const std::string& motion, const std::string& options,
                           const std::string& name) const {
    const std::string out = Path(name);
    const CliRun r = Analyze(kArm26 + " --motion " + motion + " --out " + out + options);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    StoTable arms = ReadStoTable(out + "/MomentArm_r_elbow_flex.sto");
    EXPECT_EQ(arms.rows.size(), 1u);
    return arms;
  }
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
  // arm26 with its ellipsoids made MyPluginWrapObject (a type Sinew does not wrap over).
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

TEST_F(AnalyzeCliTest, FunctionBasedPathsGetTheirTables) {
  // tests/data/sinew/function_based_paths.osim: the spring's length is the polynomial
  // L = 0.3 + 0.02 q2 - 0.01 q2^2 - 0.04 q1 + 0.015 q1 q2 + 0.005 q1^2 of its coordinates; the
  // actuator's length 0.2 q1 + 0.01 with the moment arm function 0.1 q1 - 0.05. A motion of
  // polynomials q1 = 0.5 t, q2 = -0.3 t (radians) over 11 rows: the quintic spline reproduces
  // them and their speeds 0.5 and -0.3 rad/s (to its fit, ~1e-12 here).
  const std::string motion = Path("swing.mot");
  {
    std::ofstream out(motion);
    out << "swing\nversion=1\nnRows=11\nnColumns=3\ninDegrees=no\nendheader\ntime\tq1\tq2\n";
    for (int k = 0; k <= 10; ++k) {
      const double t = 0.1 * k;
      out << t << "\t" << 0.5 * t << "\t" << -0.3 * t << "\n";
    }
  }
  const CliRun r = Analyze(std::string(SINEW_TEST_DATA_DIR) + "/sinew/function_based_paths.osim" +
                           " --motion " + motion + " --out " + Path("out"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const StoTable lengths = ReadStoTable(Path("out/Length.sto"));
  const StoTable speeds = ReadStoTable(Path("out/LengtheningSpeed.sto"));
  const StoTable arm1 = ReadStoTable(Path("out/MomentArm_q1.sto"));
  const StoTable arm2 = ReadStoTable(Path("out/MomentArm_q2.sto"));
  ASSERT_EQ(lengths.rows.size(), 11u);
  const int spring = lengths.Column("spring"), act = lengths.Column("act");
  ASSERT_GE(spring, 0);
  ASSERT_GE(act, 0);
  for (size_t row = 0; row < lengths.rows.size(); ++row) {
    const double t = lengths.rows[row][0], q1 = 0.5 * t, q2 = -0.3 * t;
    const double dL1 = -0.04 + 0.015 * q2 + 0.01 * q1, dL2 = 0.02 - 0.02 * q2 + 0.015 * q1;
    // The table's numbers are written with enough digits for 1e-12.
    EXPECT_NEAR(lengths.rows[row][spring],
                0.3 + 0.02 * q2 - 0.01 * q2 * q2 - 0.04 * q1 + 0.015 * q1 * q2 + 0.005 * q1 * q1,
                1e-12);
    EXPECT_NEAR(speeds.rows[row][spring], dL1 * 0.5 + dL2 * -0.3, 1e-9) << t;
    EXPECT_NEAR(arm1.rows[row][spring], -dL1, 1e-12);
    EXPECT_NEAR(arm2.rows[row][spring], -dL2, 1e-12);
    EXPECT_NEAR(lengths.rows[row][act], 0.2 * q1 + 0.01, 1e-12);
    EXPECT_NEAR(arm1.rows[row][act], 0.1 * q1 - 0.05, 1e-12);
    EXPECT_EQ(arm2.rows[row][act], 0.0);
  }
}

TEST_F(AnalyzeCliTest, DoubleCylinderObstaclePathsGetTheirTables) {
  // tests/data/sinew/double_cylinder.osim: two paths over WrapDoubleCylinderObst objects. The
  // elbow q2 turns from -0.5 to 0.9 rad at 1 rad/s (q1 = 0), in 141 rows: the extensor goes
  // from straight to round V, then round both (short of its snap at 0.976 rad).
  const std::string motion = Path("flex.mot");
  {
    std::ofstream out(motion);
    out << "flex\nversion=1\nnRows=141\nnColumns=3\ninDegrees=no\nendheader\ntime\tq1\tq2\n";
    for (int k = 0; k <= 140; ++k) out << 0.01 * k << "\t0\t" << -0.5 + 0.01 * k << "\n";
  }
  const CliRun r = Analyze(std::string(SINEW_TEST_DATA_DIR) + "/sinew/double_cylinder.osim" +
                           " --motion " + motion + " --out " + Path("out"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");  // every wrap object is applied: nothing to warn about
  const StoTable lengths = ReadStoTable(Path("out/Length.sto"));
  const StoTable speeds = ReadStoTable(Path("out/LengtheningSpeed.sto"));
  const StoTable arm1 = ReadStoTable(Path("out/MomentArm_q1.sto"));
  const StoTable arm2 = ReadStoTable(Path("out/MomentArm_q2.sto"));
  ASSERT_EQ(lengths.rows.size(), 141u);
  const int ext = lengths.Column("ext");
  ASSERT_GE(ext, 0);
  ASSERT_GE(lengths.Column("ext_tilted"), 0);
  // At q2 = -0.5 the extensor clears both cylinders: the straight line from ground
  // (-0.03, -0.1) to the lower link's (-0.015, -0.12), the link turned -0.5 rad about the elbow
  // (0, -0.3); its moment arms are minus the line's direction dotted with the insertion's
  // velocity per unit rotation about z (about the origin for q1, the elbow for q2).
  const Eigen::Vector3d p(-0.03, -0.1, 0.0), elbow(0.0, -0.3, 0.0), z = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d s = elbow + Eigen::AngleAxisd(-0.5, z) * Eigen::Vector3d(-0.015, -0.12, 0);
  const Eigen::Vector3d e = (s - p).normalized();
  EXPECT_NEAR(lengths.rows[0][ext], (s - p).norm(), 1e-12);
  EXPECT_NEAR(arm1.rows[0][ext], -e.dot(z.cross(s)), 1e-12);
  EXPECT_NEAR(arm2.rows[0][ext], -e.dot(z.cross(s - elbow)), 1e-12);
  // The lengthening speed integrates to the length change: the trapezoidal rule's error is at
  // most T h^2 max|L''| / 12 = 1.4 s (0.01 s)^2 (1 m/s^2) / 12 ~ 1.2e-5 m, with |L''| (the
  // rate of change of a moment arm of centimetres over tenths of a radian) below 1 m/rad^2.
  for (size_t c = 1; c < speeds.labels.size(); ++c) {
    double integral = 0.0;
    for (size_t row = 1; row < speeds.rows.size(); ++row) {
      integral += 0.5 * (speeds.rows[row][c] + speeds.rows[row - 1][c]) * 0.01;
    }
    EXPECT_NEAR(integral, lengths.rows.back()[c] - lengths.rows.front()[c], 1.2e-5)
        << speeds.labels[c];
  }
  // q1 is still and q2 turns at 1 rad/s, so the speed is minus the q2 moment arm.
  for (size_t row = 0; row < speeds.rows.size(); ++row) {
    EXPECT_NEAR(speeds.rows[row][ext], -arm2.rows[row][ext], 1e-9) << row;
  }
}

TEST_F(AnalyzeCliTest, CylinderRefinementOptionChangesOnlyPathsOverOneCylinder) {
  // arm26 at the elbow's full extension (docs/wrapping.md): BRA (one WrapCylinder) is refined
  // only under "always", so its elbow moment arm differs between the rules (by 2.2e-4 m);
  // TRIlong (three wrap objects) is refined under both rules and BIClong, BICshort (no
  // cylinder) never: those are identical.
  const std::string motion = WriteArmPose(0.0, 0.0);
  StoTable arms[3];
  const char* rules[3] = {"", " --cylinder-refinement several-wraps",
                          " --cylinder-refinement always"};
  for (int k = 0; k < 3; ++k) {
    arms[k] = ElbowMomentArms(motion, rules[k], "out" + std::to_string(k));
    ASSERT_EQ(arms[k].rows.size(), 1u);
  }
  const int bra = arms[0].Column("BRA");
  ASSERT_GE(bra, 0);
  EXPECT_EQ(arms[0].rows[0], arms[1].rows[0]);  // the default is several-wraps
  EXPECT_GT(std::abs(arms[2].rows[0][bra] - arms[1].rows[0][bra]), 1e-4);
  for (const char* same : {"TRIlong", "BIClong", "BICshort"}) {
    const int c = arms[0].Column(same);
    ASSERT_GE(c, 0) << same;
    EXPECT_EQ(arms[2].rows[0][c], arms[1].rows[0][c]) << same;
  }
  const CliRun bad = Analyze(kArm26 + " --motion " + motion + " --out " + Path("bad") +
                             " --cylinder-refinement sometimes");
  EXPECT_EQ(bad.exit_code, 2) << bad.err;
  EXPECT_NE(bad.err.find("--cylinder-refinement"), std::string::npos) << bad.err;
}

TEST_F(AnalyzeCliTest, OpenSim44RuleChangesOnlyPathsWhoseCylinderRefinesInSeveralSteps) {
  // arm26 at elbow flexion 2 rad, shoulder 0 (docs/wrapping.md, WrapCylinder step 5): only the
  // elbow cylinder wraps TRIlong (three wrap objects, so it refines, over several steps there),
  // and OpenSim 4.4.0's check of the second tangent point moves TRIlong's elbow moment arm by
  // about 3e-6 m from 4.4.1's; BRA, TRIlat and TRImed (one wrap object each) are not refined
  // under either rule: identical.
  const std::string motion = WriteArmPose(0.0, 2.0);
  StoTable arms[2];
  const char* rules[2] = {"several-wraps", "opensim-4.4"};
  for (int k = 0; k < 2; ++k) {
    arms[k] = ElbowMomentArms(motion, std::string(" --cylinder-refinement ") + rules[k],
                              std::string("out_") + rules[k]);
    ASSERT_EQ(arms[k].rows.size(), 1u);
  }
  const int tri_long = arms[0].Column("TRIlong");
  ASSERT_GE(tri_long, 0);
  EXPECT_GT(std::abs(arms[1].rows[0][tri_long] - arms[0].rows[0][tri_long]), 1e-6);
  for (const char* same : {"BRA", "TRIlat", "TRImed", "BIClong", "BICshort"}) {
    const int c = arms[0].Column(same);
    ASSERT_GE(c, 0) << same;
    EXPECT_EQ(arms[1].rows[0][c], arms[0].rows[0][c]) << same;
  }
}

TEST_F(AnalyzeCliTest, MomentArmTablesAreOpenSimsWhereTangentPointsAreStale) {
  // arm26 at shoulder elevation 1.9635 rad, elbow 0 (a MyoConverter sweep pose): TRIlong's
  // three wrap objects leave tangent points stale (docs/paths.md), where OpenSim's moment arm
  // is not -dL/dq. The table holds OpenSim's (PathAnalysis::opensim_moment_arm), 7.9e-3 m
  // from Sinew's -dL/dq (PathAnalysis::moment_arm) there.
  const std::string motion = WriteArmPose(1.9635, 0.0);
  const CliRun r = Analyze(kArm26 + " --motion " + motion + " --out " + Path("out"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const StoTable table = ReadStoTable(Path("out") + "/MomentArm_r_shoulder_elev.sto");
  ASSERT_EQ(table.rows.size(), 1u);
  const int column = table.Column("TRIlong");
  ASSERT_GE(column, 0);

  const sinew::model::ModelSpec spec = sinew::io::ReadOsim(kArm26);
  const sinew::kinematics::KinematicTree tree(spec);
  const sinew::kinematics::CoordinateCouplers couplers(spec);
  const sinew::paths::PathSet paths(spec);
  const int shoulder = spec.FindCoordinate("r_shoulder_elev");
  const int elbow = spec.FindCoordinate("r_elbow_flex");
  ASSERT_GE(shoulder, 0);
  ASSERT_GE(elbow, 0);
  std::vector<double> q = tree.default_q();
  q[static_cast<size_t>(shoulder)] = 1.9635;
  q[static_cast<size_t>(elbow)] = 0.0;
  sinew::paths::PathAnalysis analysis(spec, tree, couplers, paths, {shoulder});
  analysis.Calc(q, std::vector<double>(q.size(), 0.0));
  size_t path = 0;
  while (path < paths.paths().size() && paths.paths()[path].name() != "TRIlong") ++path;
  ASSERT_LT(path, paths.paths().size());
  const double written = table.rows[0][column];
  // The table's 17 significant digits read back to the same double.
  EXPECT_EQ(written, analysis.opensim_moment_arm(0, path));
  EXPECT_GT(std::abs(written - analysis.moment_arm(0, path)), 5e-3);
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

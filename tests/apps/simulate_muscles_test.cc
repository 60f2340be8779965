// `sinew simulate` with muscles: equilibrium on request, the class rename OpenSim's forward
// tests use, and their errors.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "apps/cli_test_util.h"
#include "engine/test_models.h"

namespace sinew {
namespace {

using testing::CliRun;

const std::string kArm26 =
    std::string(SINEW_TEST_DATA_DIR) + "/opensim-org/opensim-models/Models/Arm26/arm26.osim";

class SimulateMusclesTest : public testing::CliTest {};

TEST_F(SimulateMusclesTest, EquilibrateMusclesMovesFibersOffTheirDefaults) {
  const CliRun plain = Run("simulate " + kArm26 + " --duration 0 --quiet --out " + Path("plain"));
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  const CliRun eq =
      Run("simulate " + kArm26 + " --duration 0 --quiet --equilibrate-muscles --out " + Path("eq"));
  ASSERT_EQ(eq.exit_code, 0) << eq.err;
  const auto a = engine::testing::ReadStoColumns(Path("plain/states.sto"));
  const auto b = engine::testing::ReadStoColumns(Path("eq/states.sto"));
  // Without equilibrium: the file's default_fiber_length (TRIlong's optimal length 0.134 m).
  EXPECT_EQ(a.at("/forceset/TRIlong/fiber_length").front(), 0.134);
  EXPECT_NE(b.at("/forceset/TRIlong/fiber_length").front(), 0.134);
  EXPECT_EQ(b.at("/forceset/TRIlong/activation").front(), 0.05);  // the default activation
}

TEST_F(SimulateMusclesTest, RenamedClassIsSimulatedFromItsDefaultsOrFromEquilibrium) {
  const std::string rename = " --rename-force-class Thelen2003Muscle=Thelen2003Muscle_Deprecated";
  // The deprecated class starts its fibers at length 0 (OpenSim 2.x's default), so each tendon
  // takes the whole wrapped path and the elbow is flung (-130 rad/s within 3 ms, then the arm
  // flails at up to about 120 rad/s): 2 ms show the class simulated, with a warning saying why
  // such a start misbehaves.
  const CliRun run =
      Run("simulate " + kArm26 + rename + " --duration 0.002 --quiet --out " + Path("dep"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("sinew: warning: 6 muscle(s) start with fiber length 0 (TRIlong, ...;"),
            std::string::npos)
      << run.err;
  // From OpenSim's equilibrium (computeIsometricForce) the arm moves calmly: 0.2 s, every
  // state finite, every fiber balanced (no warning).
  const CliRun eq = Run("simulate " + kArm26 + rename +
                        " --duration 0.2 --quiet --equilibrate-muscles --out " + Path("eq"));
  ASSERT_EQ(eq.exit_code, 0) << eq.err;
  EXPECT_EQ(eq.err.find("warning"), std::string::npos) << eq.err;
  const auto states = engine::testing::ReadStoColumns(Path("eq/states.sto"));
  EXPECT_NEAR(states.at("time").back(), 0.2, 1e-12);
  for (const auto& [label, values] : states) {
    for (double v : values) ASSERT_TRUE(std::isfinite(v)) << label;
  }
  for (const char* muscle : {"TRIlong", "TRIlat", "TRImed", "BIClong", "BICshort", "BRA"}) {
    const std::string prefix = std::string("/forceset/") + muscle;
    EXPECT_EQ(states.at(prefix + "/activation").front(), 0.0) << muscle;  // OpenSim 2.x's start
    EXPECT_GT(states.at(prefix + "/fiber_length").front(), 0.0) << muscle;
  }
  const CliRun bad = Run("simulate " + kArm26 +
                         " --rename-force-class Thelen2003Muscle --duration 0 --out " + Path("b"));
  EXPECT_EQ(bad.exit_code, 2) << bad.err;
  EXPECT_NE(bad.err.find("--rename-force-class: expects OLD=NEW"), std::string::npos) << bad.err;
}

// arm26's muscles read as Schutte1993Muscle (OpenSim's name for Schutte1993Muscle_Deprecated;
// the Thelen properties it does not have are not read): simulated under --strict, from
// equilibrium at OpenSim's default activation 0, with OpenSim 4's state labels; inspect lists
// nothing as not simulated.
TEST_F(SimulateMusclesTest, SchutteMusclesSimulateStrictlyFromEquilibrium) {
  std::string text = testing::ReadText(kArm26);
  for (size_t at = text.find("Thelen2003Muscle"); at != std::string::npos;
       at = text.find("Thelen2003Muscle", at)) {
    text.replace(at, 16, "Schutte1993Muscle");
  }
  const std::string model = Path("schutte.osim");
  std::ofstream(model) << text;
  const CliRun run =
      Run("simulate " + model + " --duration 0.05 --strict --equilibrate-muscles --quiet --out " +
          Path("run"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto states = engine::testing::ReadStoColumns(Path("run/states.sto"));
  for (const char* muscle : {"TRIlong", "TRIlat", "TRImed", "BIClong", "BICshort", "BRA"}) {
    const std::string prefix = std::string("/forceset/") + muscle;
    EXPECT_EQ(states.at(prefix + "/activation").front(), 0.0) << muscle;
    EXPECT_GT(states.at(prefix + "/fiber_length").front(), 0.0) << muscle;
  }
  const CliRun inspect = Run("inspect " + model);
  ASSERT_EQ(inspect.exit_code, 0) << inspect.err;
  EXPECT_NE(inspect.out.find("Schutte1993Muscle: 6"), std::string::npos) << inspect.out;
  EXPECT_NE(inspect.out.find("not simulated (0)"), std::string::npos) << inspect.out;
}

TEST_F(SimulateMusclesTest, FiberAtItsMinimumLengthIsAWarning) {
  // Without pennation the minimum fiber length is 0; a tendon 0.5% past its slack length pulls
  // less than even a zero-length fiber at activation 0.2 (0.2 fal(0) > fse(1.005)).
  const std::string model = Path("short.osim");
  std::ofstream(model) << R"(<OpenSimDocument Version="40000"><Model name="m">
<Ground name="ground"/><BodySet><objects><Body name="block"><mass>2</mass>
<inertia>0.1 0.1 0.1 0 0 0</inertia></Body></objects></BodySet>
<JointSet><objects><SliderJoint name="slide"><socket_parent_frame>/ground</socket_parent_frame>
<socket_child_frame>/bodyset/block</socket_child_frame><coordinates><Coordinate name="x">
<default_value>0.1</default_value><locked>true</locked></Coordinate></coordinates></SliderJoint>
</objects></JointSet><ForceSet><objects><Thelen2003Muscle name="musc"><GeometryPath>
<PathPointSet><objects><PathPoint name="p1"><socket_parent_frame>/ground</socket_parent_frame>
<location>-0.3 0 0</location></PathPoint><PathPoint name="p2"><socket_parent_frame>/bodyset/block
</socket_parent_frame><location>0 0 0</location></PathPoint></objects></PathPointSet>
</GeometryPath><optimal_fiber_length>0.1</optimal_fiber_length>
<tendon_slack_length>0.398</tendon_slack_length><default_activation>0.2</default_activation>
</Thelen2003Muscle></objects></ForceSet></Model></OpenSimDocument>)";
  const CliRun run =
      Run("simulate " + model + " --duration 0 --quiet --equilibrate-muscles --out " + Path("out"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("sinew: warning: /forceset/musc: no fiber length balances the tendon"),
            std::string::npos)
      << run.err;
}

TEST_F(SimulateMusclesTest, DeprecatedMusclesTendonHeldAtSlackIsAWarning) {
  // A path 0.30 m long over a tendon slack at 0.27 m, activation 0 (OpenSim 2.x's start): the
  // slack tendon's small stiffness (0.001 Fiso) pulls harder than the passive fiber can with the
  // tendon at or beyond slack, and OpenSim's iteration never shortens it below slack.
  const std::string model =
      std::string(SINEW_TEST_DATA_DIR) + "/sinew/slack_deprecated_muscle.osim";
  const CliRun run =
      Run("simulate " + model + " --duration 0 --quiet --equilibrate-muscles --out " + Path("out"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("sinew: warning: /forceset/musc: OpenSim's equilibrium iteration ended "
                         "with the tendon at its slack length"),
            std::string::npos)
      << run.err;
  const auto states = engine::testing::ReadStoColumns(Path("out/states.sto"));
  // The fiber across the rest of the path at the muscle's width: hypot(0.03, 0.12 sin 0.2).
  EXPECT_NEAR(states.at("/forceset/musc/fiber_length").front(),
              std::hypot(0.03, 0.12 * std::sin(0.2)), 1e-12);
}

}  // namespace
}  // namespace sinew

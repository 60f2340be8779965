// `sinew simulate` driving actuators (the seed's API through the CLI): --excitation,
// --controls, --activate-actuators and --export, checked against closed forms; and
// `sinew inspect --json` reporting what the parser built. (--strict: not_simulated_test.cc.)
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "apps/cli_test_util.h"
#include "engine/test_models.h"

namespace sinew {
namespace {

using engine::testing::ReadStoColumns;

const std::string kChrono =
    std::string(SINEW_TEST_DATA_DIR) + "/projectchrono/chrono/data/opensim/";
// torque-actuator.osim: a z pin, rod1 with inertia 1.25 kg m^2 about it, q1(0) = -0.78539816,
// no gravity; actuator "grav" puts -9.8 e(t) N m on rod1.
constexpr double kQ0 = -0.78539816;
constexpr double kInertia = 1.25;
// The runs use accuracy 1e-10; q is then good to ~1e-9 rad.
constexpr double kTolerance = 1e-7;

using testing::CliRun;

class SimulateActuatorsTest : public testing::CliTest {
 protected:
  // q1 at the last row (t = 1 s) of a run of torque-actuator.osim with `options`, written to
  // the folder `name`.
  double FinalQ1(const std::string& name, const std::string& options) const {
    const CliRun run =
        Run("simulate " + kChrono + "torque-actuator.osim --duration 1 --accuracy 1e-10 " +
            options + " --quiet --out " + Path(name));
    EXPECT_EQ(run.exit_code, 0) << run.err;
    const auto columns = ReadStoColumns(Path(name) + "/states.sto");
    EXPECT_NEAR(columns.at("time").back(), 1.0, 1e-12);
    return columns.at("/jointset/pin1/q1/value").back();
  }
};

TEST_F(SimulateActuatorsTest, RampExcitationGivesTheClosedFormCubic) {
  // e(t) = t: q = q0 - 9.8 t^3 / (6 I).
  EXPECT_NEAR(FinalQ1("ramp", "--excitation grav=ramp:0,1"), kQ0 - 9.8 / (6 * kInertia),
              kTolerance);
}

TEST_F(SimulateActuatorsTest, ConstantExcitationAndActivateActuatorsGiveTheParabola) {
  // e = 0.5: q = q0 - 0.5 * 9.8 * 0.5 / I at t = 1; e = 1 from --activate-actuators.
  EXPECT_NEAR(FinalQ1("constant", "--excitation grav=constant:0.5"),
              kQ0 - 0.5 * 9.8 * 0.5 / kInertia, kTolerance);
  EXPECT_NEAR(FinalQ1("activate", "--activate-actuators"), kQ0 - 0.5 * 9.8 / kInertia, kTolerance);
}

TEST_F(SimulateActuatorsTest, SineExcitationMatchesItsDoubleIntegral) {
  // e = sin(2 pi t) (1 Hz): q'' = -9.8 sin(2 pi t) / I, q'(0) = 0, so
  // q(1) = q0 - 9.8 / I * (t / (2 pi) - sin(2 pi t) / (2 pi)^2) at t = 1.
  const double w = 2 * 3.14159265358979323846;
  EXPECT_NEAR(FinalQ1("sine", "--excitation grav=sine:1,1,0"), kQ0 - 9.8 / kInertia * (1.0 / w),
              kTolerance);
}

TEST_F(SimulateActuatorsTest, ControlsFileDrivesTheActuator) {
  // The ControlSet ramps "grav.excitation" as e = t.
  EXPECT_NEAR(FinalQ1("controls", "--controls " + std::string(SINEW_TEST_DATA_DIR) +
                                      "/sinew/grav_ramp_controls.xml"),
              kQ0 - 9.8 / (6 * kInertia), kTolerance);
}

TEST_F(SimulateActuatorsTest, BadExcitationsAndStrictFailuresExitWithCode2) {
  const std::string base =
      "simulate " + kChrono + "torque-actuator.osim --duration 0.1 --quiet --out " + Path("out");
  CliRun run = Run(base + " --excitation grav=triangle:1");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err,
            "sinew: error: --excitation grav=triangle:1: unknown kind 'triangle' (constant, ramp "
            "or sine)\n");
  run = Run(base + " --excitation grav=ramp:1");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err,
            "sinew: error: --excitation grav=ramp:1: expected 2 comma-separated number(s)\n");
  run = Run(base + " --excitation nobody=constant:1");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("nobody: no actuator of this name was parsed"), std::string::npos)
      << run.err;
}

TEST_F(SimulateActuatorsTest, ExportWritesAViewerOfTheRun) {
  // The viewer goes to a folder that does not exist yet.
  const std::string glb = Path("viewer/run.glb");
  const CliRun run = Run("simulate " + kChrono + "torque-actuator.osim --duration 0.5 " +
                         "--vis primitives --quiet --out " + Path("out") + " --export " + glb);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  // A GLB starts with the magic "glTF" and version 2.
  std::ifstream in(glb, std::ios::binary);
  char header[8] = {};
  in.read(header, 8);
  EXPECT_EQ(std::string(header, 4), "glTF");
  EXPECT_EQ(header[4], 2);
}

class InspectReportTest : public testing::CliTest {};

TEST_F(InspectReportTest, JsonHasWhatTheParserBuilt) {
  const CliRun run = Run("inspect --json " + kChrono + "torque-actuator.osim");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string& text = run.out;
  const nlohmann::json json = nlohmann::json::parse(text);
  const nlohmann::json& build = json.at("build");
  EXPECT_TRUE(build.at("simulatable").get<bool>());
  ASSERT_EQ(build.at("joints").size(), 1u);
  EXPECT_EQ(build.at("joints")[0].at("engine_joint"), "revolute (direct)");
  EXPECT_FALSE(build.at("joints")[0].at("standin").get<bool>());
  ASSERT_EQ(build.at("forces").size(), 1u);
  EXPECT_EQ(build.at("forces")[0].at("excitation"), "PrescribedController prescribedcontroller_");
}

}  // namespace
}  // namespace sinew

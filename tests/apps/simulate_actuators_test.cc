// `sinew simulate` driving actuators (the seed's API through the CLI): --excitation,
// --controls, --activate-actuators, --strict and --export, checked against closed forms; and
// `sinew inspect --json` reporting what the parser built.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "engine/test_models.h"

namespace {

using sinew::engine::testing::ReadStoColumns;

const std::string kChrono =
    std::string(SINEW_TEST_DATA_DIR) + "/projectchrono/chrono/data/opensim/";
// torque-actuator.osim: a z pin, rod1 with inertia 1.25 kg m^2 about it, q1(0) = -0.78539816,
// no gravity; actuator "grav" puts -9.8 e(t) N m on rod1.
constexpr double kQ0 = -0.78539816;
constexpr double kInertia = 1.25;
// The runs use accuracy 1e-10; q is then good to ~1e-9 rad.
constexpr double kTolerance = 1e-7;

int RunCli(const std::string& arguments, std::string* stdout_text = nullptr) {
  // One file per test: ctest runs the tests of this program in parallel processes.
  const std::string out_file =
      (std::filesystem::temp_directory_path() /
       ("sinew_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) +
        "_stdout.txt"))
          .string();
  const std::string command =
      std::string(SINEW_CLI_PATH) + " " + arguments + " > " + out_file + " 2>/dev/null";
  const int status = std::system(command.c_str());
  if (stdout_text) {
    std::ifstream in(out_file);
    std::stringstream buffer;
    buffer << in.rdbuf();
    *stdout_text = buffer.str();
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string TempDir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("sinew_actuators_test_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

// q1 at the last row (t = 1 s) of a run of torque-actuator.osim with `options`.
double FinalQ1(const std::string& name, const std::string& options) {
  const std::string out = TempDir(name);
  EXPECT_EQ(RunCli("simulate " + kChrono + "torque-actuator.osim --duration 1 --accuracy 1e-10 " +
                   options + " --quiet --out " + out),
            0);
  const auto columns = ReadStoColumns(out + "/states.sto");
  EXPECT_NEAR(columns.at("time").back(), 1.0, 1e-12);
  return columns.at("/jointset/pin1/q1/value").back();
}

TEST(SimulateActuatorsTest, RampExcitationGivesTheClosedFormCubic) {
  // e(t) = t: q = q0 - 9.8 t^3 / (6 I).
  EXPECT_NEAR(FinalQ1("ramp", "--excitation grav=ramp:0,1"), kQ0 - 9.8 / (6 * kInertia),
              kTolerance);
}

TEST(SimulateActuatorsTest, ConstantExcitationAndActivateActuatorsGiveTheParabola) {
  // e = 0.5: q = q0 - 0.5 * 9.8 * 0.5 / I at t = 1; e = 1 from --activate-actuators.
  EXPECT_NEAR(FinalQ1("constant", "--excitation grav=constant:0.5"),
              kQ0 - 0.5 * 9.8 * 0.5 / kInertia, kTolerance);
  EXPECT_NEAR(FinalQ1("activate", "--activate-actuators"), kQ0 - 0.5 * 9.8 / kInertia, kTolerance);
}

TEST(SimulateActuatorsTest, SineExcitationMatchesItsDoubleIntegral) {
  // e = sin(2 pi t) (1 Hz): q'' = -9.8 sin(2 pi t) / I, q'(0) = 0, so
  // q(1) = q0 - 9.8 / I * (t / (2 pi) - sin(2 pi t) / (2 pi)^2) at t = 1.
  const double w = 2 * 3.14159265358979323846;
  EXPECT_NEAR(FinalQ1("sine", "--excitation grav=sine:1,1,0"), kQ0 - 9.8 / kInertia * (1.0 / w),
              kTolerance);
}

TEST(SimulateActuatorsTest, ControlsFileDrivesTheActuator) {
  // The ControlSet ramps "grav.excitation" as e = t.
  EXPECT_NEAR(FinalQ1("controls", "--controls " + std::string(SINEW_TEST_DATA_DIR) +
                                      "/sinew/grav_ramp_controls.xml"),
              kQ0 - 9.8 / (6 * kInertia), kTolerance);
}

TEST(SimulateActuatorsTest, BadExcitationsAndStrictFailuresExitWithCode2) {
  const std::string out = TempDir("bad");
  const std::string base =
      "simulate " + kChrono + "torque-actuator.osim --duration 0.1 --quiet --out " + out;
  EXPECT_EQ(RunCli(base + " --excitation grav=triangle:1"), 2);
  EXPECT_EQ(RunCli(base + " --excitation grav=ramp:1"), 2);
  EXPECT_EQ(RunCli(base + " --excitation nobody=constant:1"), 2);
  // double_pendulum.osim has nothing the engine leaves out, so --strict passes; arm26's
  // muscles are not simulated yet, so --strict refuses it.
  EXPECT_EQ(RunCli("simulate " + kChrono +
                   "double_pendulum.osim --duration 0.01 --strict --quiet " + "--out " + out),
            0);
  const std::string arm26 = std::string(SINEW_TEST_DATA_DIR) + "/opensim-org/opensim-core/" +
                            "OpenSim/Simulation/Test/arm26.osim";
  ASSERT_TRUE(std::filesystem::exists(arm26));
  EXPECT_EQ(RunCli("simulate " + arm26 + " --duration 0.01 --strict --quiet --out " + out), 2);
}

TEST(SimulateActuatorsTest, ExportWritesAViewerOfTheRun) {
  const std::string out = TempDir("export");
  ASSERT_EQ(RunCli("simulate " + kChrono + "torque-actuator.osim --duration 0.5 --vis primitives " +
                   "--quiet --out " + out + " --export " + out + "/run.glb"),
            0);
  // A GLB starts with the magic "glTF" and version 2.
  std::ifstream glb(out + "/run.glb", std::ios::binary);
  char header[8] = {};
  glb.read(header, 8);
  EXPECT_EQ(std::string(header, 4), "glTF");
  EXPECT_EQ(header[4], 2);
}

TEST(InspectReportTest, JsonHasWhatTheParserBuilt) {
  std::string text;
  ASSERT_EQ(RunCli("inspect --json " + kChrono + "torque-actuator.osim", &text), 0);
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

// `sinew simulate` end to end: SinglePin.osim from its initial-states file reproduces OpenSim's
// stored states; output files have the documented columns; bad models exit with code 2.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "engine/test_models.h"

namespace {

using sinew::engine::testing::ReadStoColumns;

const std::string kResources = std::string(SINEW_TEST_DATA_DIR) +
                               "/opensim-org/opensim-core/Applications/Analyze/tests/resources/";

int RunCli(const std::string& arguments) {
  const std::string command = std::string(SINEW_CLI_PATH) + " " + arguments + " > /dev/null 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string TempDir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("sinew_simulate_test_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

TEST(SimulateCommandTest, SinglePinReproducesOpenSim) {
  const std::string out = TempDir("single_pin");
  ASSERT_EQ(
      RunCli("simulate " + kResources + "SinglePin.osim --duration 3 --accuracy 1e-10 " +
             "--initial-states " + kResources + "SinglePin_InitialStates.sto --quiet --out " + out),
      0);
  const auto ours = ReadStoColumns(out + "/states.sto");
  const auto ref = ReadStoColumns(kResources + "SinglePin_states.sto");
  const auto& q = ours.at("/jointset/pin1/r1_z/value");
  const auto& u = ours.at("/jointset/pin1/r1_z/speed");
  ASSERT_EQ(ours.at("time").size(), 301u);  // 0 to 3 s every 0.01 s
  double dq = 0.0, du = 0.0;
  for (size_t row = 0; row < ref.at("time").size(); ++row) {
    // OpenSim's rows are the report times 0, 0.01, ... (plus a final duplicate row).
    const size_t i = static_cast<size_t>(std::lround(ref.at("time")[row] / 0.01));
    ASSERT_LT(i, q.size());
    ASSERT_NEAR(ours.at("time")[i], ref.at("time")[row], 1e-12);
    dq = std::max(dq, std::abs(q[i] - ref.at("r1_z")[row]));
    du = std::max(du, std::abs(u[i] - ref.at("r1_z_u")[row]));
  }
  EXPECT_LT(dq, 1e-6);
  EXPECT_LT(du, 1e-5);
  // bodies.sto: time + 6 columns per body (ground, rod1) + 3 for the whole-model mass centre.
  const auto bodies = ReadStoColumns(out + "/bodies.sto");
  EXPECT_EQ(bodies.size(), 1u + 12u + 3u);
  // rod1's mass centre hangs 0.5 m from the pivot at angle q: x = 0.5 sin q, y = -0.5 cos q.
  EXPECT_NEAR(bodies.at("rod1_X")[100], 0.5 * std::sin(q[100]), 1e-9);
  EXPECT_NEAR(bodies.at("rod1_Y")[100], -0.5 * std::cos(q[100]), 1e-9);
}

TEST(SimulateCommandTest, FixedStepIntegratorRuns) {
  const std::string out = TempDir("euler");
  ASSERT_EQ(RunCli("simulate " + kResources + "DoublePendulum3D.osim --duration 0.5 " +
                   "--integrator euler --step 1e-3 --report-interval 0.1 --quiet --out " + out),
            0);
  const auto ours = ReadStoColumns(out + "/states.sto");
  EXPECT_EQ(ours.at("time").size(), 6u);
  EXPECT_NEAR(ours.at("time").back(), 0.5, 1e-12);
}

// A locked coordinate is held at the value the initial-states file gives it (r2_x = 1 rad; the
// model's default_value is 1.0588), as OpenSim's Forward tool does.
TEST(SimulateCommandTest, LockedCoordinateHoldsItsInitialStateValue) {
  const std::string out = TempDir("locked");
  std::ifstream in(kResources + "DoublePendulum3D.osim");
  std::stringstream text;
  text << in.rdbuf();
  std::string model = text.str();
  const std::string unlocked = "<locked> false </locked>";
  const size_t first = model.find(unlocked);
  const size_t second = model.find(unlocked, first + 1);
  ASSERT_NE(second, std::string::npos);
  model.replace(second, unlocked.size(), "<locked> true </locked>");
  const std::string file = out + "/locked.osim";
  std::ofstream(file) << model;
  ASSERT_EQ(RunCli("simulate " + file + " --duration 1 --accuracy 1e-9 --initial-states " +
                   kResources + "DoublePendulum3D_InitialStates.sto --quiet --out " + out),
            0);
  const auto ours = ReadStoColumns(out + "/states.sto");
  const auto& r2 = ours.at("/jointset/pin2/r2_x/value");
  const auto& r1 = ours.at("/jointset/pin1/r1_z/value");
  ASSERT_EQ(r2.size(), 101u);
  for (size_t i = 0; i < r2.size(); ++i) EXPECT_NEAR(r2[i], 1.0, 1e-10);
  EXPECT_LT(r1.back(), 0.9);  // pin 1 swings
}

TEST(SimulateCommandTest, BadInputExitsWithCode2) {
  const std::string out = TempDir("bad");
  // Every body massless: a kinematics-only model cannot be simulated.
  std::ifstream in(kResources + "SinglePin.osim");
  std::stringstream text;
  text << in.rdbuf();
  std::string model = text.str();
  const std::string mass = "0.75000000";
  model.replace(model.find(mass), mass.size(), "0.00000000");
  const std::string massless = out + "/massless.osim";
  std::ofstream(massless) << model;
  EXPECT_EQ(RunCli("simulate " + massless + " --duration 1 --quiet --out " + out), 2);
  EXPECT_EQ(RunCli("simulate " + out + "/missing.osim --duration 1 --quiet --out " + out), 2);
  EXPECT_EQ(RunCli("simulate " + kResources + "SinglePin.osim --duration 1 --integrator nope " +
                   "--quiet --out " + out),
            2);
  EXPECT_EQ(RunCli("simulate " + kResources + "SinglePin.osim --duration 1 --initial-states " +
                   out + "/missing.sto --quiet --out " + out),
            2);
}

}  // namespace

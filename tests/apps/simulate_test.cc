// `sinew simulate` end to end: SinglePin.osim from its initial-states file reproduces OpenSim's
// stored states; the euler integrator converges at first order to rk45's trajectory; output
// files have the documented columns; bad models exit with code 2.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "apps/cli_test_util.h"
#include "engine/test_models.h"

namespace sinew {
namespace {

using engine::testing::ReadStoColumns;

const std::string kResources = std::string(SINEW_TEST_DATA_DIR) +
                               "/opensim-org/opensim-core/Applications/Analyze/tests/resources/";

using testing::CliRun;

class SimulateCommandTest : public testing::CliTest {
 protected:
  // Runs `sinew simulate ARGS --quiet --out DIR` into the test's folder DIR = `out`; returns
  // the exit code.
  int Simulate(const std::string& args, const std::string& out) const {
    last_ = Run("simulate " + args + " --quiet --out " + Path(out));
    return last_.exit_code;
  }
  mutable CliRun last_;
};

TEST_F(SimulateCommandTest, SinglePinReproducesOpenSim) {
  ASSERT_EQ(Simulate(kResources + "SinglePin.osim --duration 3 --accuracy 1e-10 " +
                         "--initial-states " + kResources + "SinglePin_InitialStates.sto",
                     "single_pin"),
            0)
      << last_.err;
  const std::string out = Path("single_pin");
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

// The euler integrator is first order: its error against a tight rk45 run (accuracy 1e-10,
// error ~1e-9) is e(h) = C h + O(h^2). So halving the step halves the error (the ratio
// e(h)/e(h/2) is 2 up to O(h)), and Richardson extrapolation 2 y(h/2) - y(h) cancels the C h
// term, leaving an O(h^2) error, a factor O(h / T) smaller than e(h/2) for the pendulum's time
// scale T ~ 1 s. Measured (h = 1e-3 s, DoublePendulum3D, 0.5 s): e(h) = 9.1e-3,
// e(h/2) = 4.6e-3, ratio 1.997, extrapolated error 1.2e-5.
TEST_F(SimulateCommandTest, EulerTrajectoryConvergesAtFirstOrder) {
  const std::string model =
      kResources + "DoublePendulum3D.osim --duration 0.5 " + "--report-interval 0.1";
  ASSERT_EQ(Simulate(model + " --accuracy 1e-10", "rk45"), 0) << last_.err;
  ASSERT_EQ(Simulate(model + " --integrator euler --step 1e-3", "euler_h"), 0) << last_.err;
  ASSERT_EQ(Simulate(model + " --integrator euler --step 5e-4", "euler_h2"), 0) << last_.err;
  const auto ref = ReadStoColumns(Path("rk45/states.sto"));
  const auto coarse = ReadStoColumns(Path("euler_h/states.sto"));
  const auto fine = ReadStoColumns(Path("euler_h2/states.sto"));
  ASSERT_EQ(ref.at("time").size(), 6u);  // 0, 0.1, ..., 0.5
  double e_coarse = 0, e_fine = 0, e_extrapolated = 0;
  for (const auto& [label, values] : ref) {
    ASSERT_EQ(coarse.at(label).size(), values.size()) << label;
    ASSERT_EQ(fine.at(label).size(), values.size()) << label;
    for (size_t i = 0; i < values.size(); ++i) {
      if (label == "time") {
        EXPECT_NEAR(coarse.at(label)[i], values[i], 1e-12);
        EXPECT_NEAR(fine.at(label)[i], values[i], 1e-12);
        continue;
      }
      e_coarse = std::max(e_coarse, std::abs(coarse.at(label)[i] - values[i]));
      e_fine = std::max(e_fine, std::abs(fine.at(label)[i] - values[i]));
      const double extrapolated = 2 * fine.at(label)[i] - coarse.at(label)[i];
      e_extrapolated = std::max(e_extrapolated, std::abs(extrapolated - values[i]));
    }
  }
  EXPECT_EQ(ref.size(), 5u);  // time, and value and speed of r1_z and r2_x
  EXPECT_GT(e_coarse, 1e-6);  // Euler's error is far above the reference's
  EXPECT_NEAR(e_coarse / e_fine, 2.0, 0.1);
  EXPECT_LT(e_extrapolated, 0.05 * e_fine);
}

// A locked coordinate is held at the value the initial-states file gives it (r2_x = 1 rad; the
// model's default_value is 1.0588), as OpenSim's Forward tool does.
TEST_F(SimulateCommandTest, LockedCoordinateHoldsItsInitialStateValue) {
  const std::string out = Path("locked");
  std::filesystem::create_directories(out);
  std::string model = testing::ReadText(kResources + "DoublePendulum3D.osim");
  const std::string unlocked = "<locked> false </locked>";
  const size_t first = model.find(unlocked);
  const size_t second = model.find(unlocked, first + 1);
  ASSERT_NE(second, std::string::npos);
  model.replace(second, unlocked.size(), "<locked> true </locked>");
  const std::string file = out + "/locked.osim";
  std::ofstream(file) << model;
  ASSERT_EQ(Simulate(file + " --duration 1 --accuracy 1e-9 --initial-states " + kResources +
                         "DoublePendulum3D_InitialStates.sto",
                     "locked"),
            0)
      << last_.err;
  const auto ours = ReadStoColumns(out + "/states.sto");
  const auto& r2 = ours.at("/jointset/pin2/r2_x/value");
  const auto& r1 = ours.at("/jointset/pin1/r1_z/value");
  ASSERT_EQ(r2.size(), 101u);
  for (size_t i = 0; i < r2.size(); ++i) EXPECT_NEAR(r2[i], 1.0, 1e-10);
  EXPECT_LT(r1.back(), 0.9);  // pin 1 swings
}

TEST_F(SimulateCommandTest, BadInputExitsWithCode2) {
  // Every body massless: a kinematics-only model cannot be simulated.
  std::string model = testing::ReadText(kResources + "SinglePin.osim");
  const std::string mass = "0.75000000";
  model.replace(model.find(mass), mass.size(), "0.00000000");
  const std::string massless = Path("massless.osim");
  std::ofstream(massless) << model;
  EXPECT_EQ(Simulate(massless + " --duration 1", "out"), 2);
  EXPECT_NE(last_.err.find("sinew: error: "), std::string::npos) << last_.err;
  EXPECT_NE(last_.err.find("mass"), std::string::npos) << last_.err;
  EXPECT_EQ(Simulate(Path("missing.osim") + " --duration 1", "out"), 2);
  EXPECT_NE(last_.err.find("sinew: error: " + Path("missing.osim")), std::string::npos)
      << last_.err;
  EXPECT_EQ(Simulate(kResources + "SinglePin.osim --duration 1 --integrator nope", "out"), 2);
  EXPECT_NE(last_.err.find("nope"), std::string::npos) << last_.err;
  EXPECT_EQ(
      Simulate(kResources + "SinglePin.osim --duration 1 --initial-states " + Path("missing.sto"),
               "out"),
      2);
  EXPECT_NE(last_.err.find("sinew: error: " + Path("missing.sto") + ": cannot open file"),
            std::string::npos)
      << last_.err;
}

}  // namespace
}  // namespace sinew

// `sinew simulate` writing forces.sto (OpenSim's ForceReporter layout) checked against hand
// computations from the same run's states.sto; --external-loads and --disable-force: results,
// exit codes and messages.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "apps/cli_test_util.h"
#include "engine/test_models.h"

namespace sinew {
namespace {

using engine::testing::ReadStoColumns;
using testing::CliRun;

const std::string kData = SINEW_TEST_DATA_DIR;
const std::string kForward =
    kData + "/opensim-org/opensim-core/Applications/Forward/tests/resources/";
const std::string kTorqueActuator =
    kData + "/projectchrono/chrono/data/opensim/torque-actuator.osim";

class SimulateForcesTest : public testing::CliTest {
 protected:
  // Runs `sinew simulate ARGS --quiet --out <folder>` and reads the folder's `file`.
  std::map<std::string, std::vector<double>> SimulateAndRead(const std::string& args,
                                                             const std::string& folder,
                                                             const std::string& file) const {
    const CliRun run = Run("simulate " + args + " --quiet --out " + Path(folder));
    EXPECT_EQ(run.exit_code, 0) << run.err;
    return ReadStoColumns(Path(folder + "/" + file));
  }
};

TEST_F(SimulateForcesTest, SpringColumnsAreTheSpringLawsOfTheReportedStates) {
  // springs.osim: block_spring (SpringGeneralizedForce, k 50 N/m, rest 0.3 m, no viscosity) on
  // block_x; arm_spring (PointToPointSpring, k 20 N/m, rest 0.2 m) from ground (0.3, -0.8, 0)
  // to point (0, -1, 0) of the arm; arm_limit (CoordinateLimitForce).
  const auto forces = SimulateAndRead(
      kData + "/sinew/springs.osim --duration 0.5 --report-interval 0.05", "out", "forces.sto");
  const auto states = ReadStoColumns(Path("out/states.sto"));
  const auto& x = states.at("/jointset/block_slide/block_x/value");
  ASSERT_EQ(forces.at("time").size(), x.size());
  ASSERT_EQ(forces.count("arm_limit"), 1u);
  ASSERT_EQ(forces.count("PotentialEnergy"), 1u);
  for (size_t i = 0; i < x.size(); ++i) {
    // Both files print shortest round-trip numbers: the law holds to rounding.
    EXPECT_NEAR(forces.at("block_spring_Force")[i], -50.0 * (x[i] - 0.3), 1e-12) << i;
    // The force on ground is k (d - L) along the unit vector towards the arm's point.
    const Vec3 p1(forces.at("arm_spring.ground.point.X")[i],
                  forces.at("arm_spring.ground.point.Y")[i],
                  forces.at("arm_spring.ground.point.Z")[i]);
    const Vec3 p2(forces.at("arm_spring.arm.point.X")[i], forces.at("arm_spring.arm.point.Y")[i],
                  forces.at("arm_spring.arm.point.Z")[i]);
    EXPECT_EQ(p1, Vec3(0.3, -0.8, 0));
    const Vec3 hand = 20.0 * ((p2 - p1).norm() - 0.2) * (p2 - p1).normalized();
    for (int k = 0; k < 3; ++k) {
      const std::string axis(1, "XYZ"[k]);
      EXPECT_NEAR(forces.at("arm_spring.ground.force." + axis)[i], hand[k], 1e-12) << i;
      EXPECT_NEAR(forces.at("arm_spring.arm.force." + axis)[i], -hand[k], 1e-12) << i;
    }
  }
}

TEST_F(SimulateForcesTest, ActuatorColumnIsOptimalForceTimesExcitation) {
  // torque-actuator.osim: TorqueActuator grav, optimal_force 9.8; excitation e(t) = 2 t.
  const auto forces = SimulateAndRead(
      kTorqueActuator + " --duration 1 --report-interval 0.1 --excitation grav=ramp:0,2", "out",
      "forces.sto");
  ASSERT_EQ(forces.size(), 2u);  // time, grav
  const auto& t = forces.at("time");
  ASSERT_EQ(t.size(), 11u);
  for (size_t i = 0; i < t.size(); ++i) EXPECT_NEAR(forces.at("grav")[i], 9.8 * 2 * t[i], 1e-12);
}

TEST_F(SimulateForcesTest, ExternalLoadsReplaceGravityAndAreReported) {
  const std::string common = " --duration 1 --report-interval 0.1 --accuracy 1e-10 --quiet";
  const CliRun gravity =
      Run("simulate " + kForward + "pendulum.osim" + common + " --out " + Path("g"));
  const CliRun external =
      Run("simulate " + kForward + "pendulum_no_gravity.osim" + common + " --external-loads " +
          kForward + "pendulum_external_load.xml" + " --out " + Path("e"));
  ASSERT_EQ(gravity.exit_code, 0) << gravity.err;
  ASSERT_EQ(external.exit_code, 0) << external.err;
  const std::string q = "/jointset/GroundJoint/Pendulum_r1/value";
  const auto g = ReadStoColumns(Path("g/states.sto")).at(q);
  const auto e = ReadStoColumns(Path("e/states.sto")).at(q);
  ASSERT_EQ(g.size(), e.size());
  for (size_t i = 0; i < g.size(); ++i) EXPECT_NEAR(e[i], g[i], 1e-6) << i;
  // ExternalForce "gravity" on body "pendulum": force in G, point in the pendulum's frame.
  const auto forces = ReadStoColumns(Path("e/forces.sto"));
  for (const char* label : {"pendulum_gravity_Fx", "pendulum_gravity_Fz", "pendulum_gravity_px",
                            "pendulum_gravity_py", "pendulum_gravity_pz"}) {
    for (double v : forces.at(label)) EXPECT_EQ(v, 0.0) << label;
  }
  for (double v : forces.at("pendulum_gravity_Fy")) EXPECT_EQ(v, -98.0665);
  // pendulum.osim has no forces: its forces.sto holds the time column alone.
  EXPECT_EQ(ReadStoColumns(Path("g/forces.sto")).size(), 1u);
}

TEST_F(SimulateForcesTest, DisableForceLeavesItOutAndAnUnknownNameListsCloseOnes) {
  const std::string base = kData + "/sinew/springs.osim --duration 0.1 --disable-force ";
  const auto forces = SimulateAndRead(base + "block_spring", "out", "forces.sto");
  EXPECT_EQ(forces.count("block_spring_Force"), 0u);
  EXPECT_EQ(forces.count("arm_limit"), 1u);
  // Without its spring the block stays at its default 0.4 m.
  const auto states = ReadStoColumns(Path("out/states.sto"));
  for (double x : states.at("/jointset/block_slide/block_x/value")) EXPECT_EQ(x, 0.4);

  const CliRun unknown = Run("simulate " + base + "block_sprng --out " + Path("bad"));
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("springs.osim: block_sprng: cannot disable: no force has this name "
                             "(close names: block_spring)"),
            std::string::npos)
      << unknown.err;
}

TEST_F(SimulateForcesTest, BadExternalLoadsAreRefusedNamingFileLineAndColumn) {
  // A force_identifier naming no 3 columns of the data file.
  const std::string data = kForward + "pendulum_external_load.sto";
  const std::string xml = Path("loads.xml");
  std::ofstream(xml) << "<OpenSimDocument Version=\"40000\">\n<ExternalLoads name=\"l\">\n"
                        "<objects>\n<ExternalForce name=\"push\">\n"
                        "<applied_to_body>pendulum</applied_to_body>\n"
                        "<force_identifier>forse</force_identifier>\n"
                        "</ExternalForce>\n</objects>\n<datafile>" +
                            data + "</datafile>\n</ExternalLoads>\n</OpenSimDocument>\n";
  const std::string run_model = "simulate " + kForward +
                                "pendulum_no_gravity.osim --duration 0.1 --quiet --out " +
                                Path("out") + " --external-loads ";
  CliRun run = Run(run_model + xml);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find(xml + ":6: /l/push: force_identifier 'forse' names 0 columns of " + data +
                         "; it needs exactly 3"),
            std::string::npos)
      << run.err;

  // A missing data file.
  std::ofstream(xml) << "<OpenSimDocument Version=\"40000\">\n<ExternalLoads>\n<objects/>\n"
                        "<datafile>nowhere.sto</datafile>\n</ExternalLoads>\n</OpenSimDocument>\n";
  run = Run(run_model + xml);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find(xml + ":4: /externalloads/datafile: cannot read '" + Path("nowhere.sto")),
            std::string::npos)
      << run.err;

  // An applied_to_body the model does not have.
  std::ofstream(xml) << "<OpenSimDocument Version=\"40000\">\n<ExternalLoads name=\"l\">\n"
                        "<objects>\n<ExternalForce name=\"push\">\n"
                        "<applied_to_body>femur</applied_to_body>\n"
                        "<force_identifier>force</force_identifier>\n"
                        "</ExternalForce>\n</objects>\n<datafile>" +
                            data + "</datafile>\n</ExternalLoads>\n</OpenSimDocument>\n";
  run = Run(run_model + xml);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find(xml + ":5: /l/push: applied_to_body 'femur' is not a body of the model"),
            std::string::npos)
      << run.err;
}

}  // namespace
}  // namespace sinew

// `sinew simulate` on models with contact forces: contacts.sto against the Hunt-Crossley law of
// the same run's states, and bad contact parameters refused with file:line:component, exit 2.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include "apps/cli_test_util.h"
#include "engine/test_models.h"

namespace sinew {
namespace {

using engine::testing::ReadStoColumns;
using testing::CliRun;

const std::string kBall = std::string(SINEW_TEST_DATA_DIR) +
                          "/opensim-org/opensim-core/OpenSim/Simulation/Test/"
                          "BouncingBall_HuntCrossley.osim";

class SimulateContactTest : public testing::CliTest {
 protected:
  // `model` with each `from` replaced by its `to`, written into the test's folder.
  std::string Edited(const std::string& model,
                     const std::vector<std::pair<std::string, std::string>>& edits) const {
    std::string text = testing::ReadText(model);
    for (const auto& [from, to] : edits) {
      const size_t at = text.find(from);
      EXPECT_NE(at, std::string::npos) << from;
      if (at != std::string::npos) text.replace(at, from.size(), to);
    }
    const std::string path = Path("ball.osim");
    std::ofstream(path) << text;
    return path;
  }
  // Runs simulate on `model` and expects exit 2 with `file:LINE: component: ...what...`.
  void ExpectRefused(const std::string& model, const std::string& component,
                     const std::string& what) const {
    const CliRun run = Run("simulate " + model + " --duration 0.1 --quiet --out " + Path("out"));
    EXPECT_EQ(run.exit_code, 2) << run.err;
    EXPECT_TRUE(std::regex_search(run.err, std::regex("ball\\.osim:[0-9]+: " + component + ": ")))
        << run.err;
    EXPECT_NE(run.err.find(what), std::string::npos) << run.err;
  }
};

TEST_F(SimulateContactTest, ContactsTableIsTheHuntCrossleyLawOfTheReportedStates) {
  // BouncingBall_HuntCrossley.osim: a 0.5 m sphere on a 1 kg ball, starting half sunk into
  // the floor (y < 0); stiffness 1e4 and dissipation 0.75 for both materials, so k =
  // (1e4)^(2/3) / 2, and the vertical force on the ball is f = 4/3 k d sqrt(R k d) (1 + 3/2 c
  // v_n) with d = 0.5 - y and v_n = -y' (friction acts sideways only).
  const CliRun run = Run("simulate " + kBall + " --duration 1 --report-interval 0.01 --quiet --out " +
                         Path("out"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto contacts = ReadStoColumns(Path("out/contacts.sto"));
  const auto states = ReadStoColumns(Path("out/states.sto"));
  const auto& y = states.at("/jointset/ground_to_ball/ball_ty/value");
  const auto& ydot = states.at("/jointset/ground_to_ball/ball_ty/speed");
  const auto& fy = contacts.at("contact.ball.force.Y");
  const auto& ground_fy = contacts.at("contact.ground.force.Y");
  const auto& active = contacts.at("contact.active_contacts");
  ASSERT_EQ(fy.size(), y.size());
  const double k = 0.5 * std::pow(1e4, 2.0 / 3.0);
  double worst = 0.0;
  int touching = 0;
  for (size_t i = 0; i < y.size(); ++i) {
    const double d = 0.5 - y[i];
    const double f = d > 0 ? 4.0 / 3.0 * k * d * std::sqrt(0.5 * k * d) * (1 - 1.125 * ydot[i]) : 0;
    worst = std::max(worst, std::abs(fy[i] - std::max(f, 0.0)) / (1.0 + std::abs(f)));
    EXPECT_EQ(active[i], f > 0 ? 1.0 : 0.0) << i;
    EXPECT_EQ(ground_fy[i], -fy[i]);
    touching += f > 0 ? 1 : 0;
  }
  EXPECT_LT(worst, 1e-12);  // the printed digits (17) of the same states
  EXPECT_GT(touching, 0);
  // forces.sto holds the same columns (OpenSim's HuntCrossleyForce record labels).
  const auto forces = ReadStoColumns(Path("out/forces.sto"));
  EXPECT_EQ(forces.at("contact.ball.force.Y"), fy);
}

TEST_F(SimulateContactTest, BadContactParametersAreRefusedWithFileLineAndComponent) {
  ExpectRefused(Edited(kBall, {{"<stiffness>   10000.00000000 </stiffness>",
                                "<stiffness> -10000 </stiffness>"}}),
                "/forceset/contact", "stiffness is -10000; it must be >= 0");
  ExpectRefused(Edited(kBall, {{"<static_friction>       0.30000000 </static_friction>",
                                "<static_friction> -0.3 </static_friction>"}}),
                "/forceset/contact", "static_friction is -0.3; it must be >= 0");
  ExpectRefused(Edited(kBall, {{"<geometry> sphere floor </geometry>",
                                "<geometry> sphere flor </geometry>"}}),
                "/forceset/contact", "names contact geometry 'flor'");
  ExpectRefused(Edited(kBall, {{"<radius>       0.50000000 </radius>", "<radius> 0 </radius>"}}),
                "/contactgeometryset/sphere", "ContactSphere needs a radius > 0");
  ExpectRefused(Edited(kBall, {{"<ContactHalfSpace name=\"floor\">",
                                "<ContactEllipsoid name=\"floor\">"},
                               {"</ContactHalfSpace>", "</ContactEllipsoid>"}}),
                "/contactgeometryset/floor", "ContactEllipsoid is not a contact geometry");
  // BouncingBallModelEF.osim's ContactMesh names a file that is not there.
  ExpectRefused(Edited(std::string(SINEW_TEST_DATA_DIR) +
                           "/opensim-org/opensim-core/OpenSim/Simulation/Test/"
                           "BouncingBallModelEF.osim",
                       {{"<filename> sphere.obj </filename>", "<filename> nosuch.obj </filename>"}}),
                "/contactgeometryset/sphere", "mesh file 'nosuch.obj' not found");
}

}  // namespace
}  // namespace sinew

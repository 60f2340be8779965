// `sinew simulate --collision`: a ball with a ContactSphere and no contact force settles on
// the model's ContactHalfSpace through SMC (the default contact method), its contacts.sto row
// at rest carrying its weight on one contact; NSC makes it bounce and rest;
// contact options are checked (exit 2).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "apps/cli_test_util.h"
#include "engine/test_models.h"

namespace sinew {
namespace {

using engine::testing::ReadStoColumns;
using testing::CliRun;

const std::string kBall = std::string(SINEW_TEST_DATA_DIR) + "/sinew/ball_on_floor.osim";

class SimulateCollisionTest : public testing::CliTest {
 protected:
  // Runs the ball with `integrator_options` and checks contacts.sto at rest.
  void ExpectBallSettles(const std::string& integrator_options) const;
};

void SimulateCollisionTest::ExpectBallSettles(const std::string& integrator_options) const {
  // Dropped 0.2 m (restitution 0.4: its bounces die out within 0.3 s), 1.5 s at steps of
  // 1e-4 s. At rest the floor carries the weight m g = 9.80665 N; the damping makes
  // the residual oscillation negligible (decay time about 0.02 s). With euler the friction is
  // explicit: its slope u m g / v_s on the slip's effective mass (m I / (I + m r^2) = 0.29 kg)
  // must keep h below 2 m_eff v_s / (u m g), so the slip speed is 0.01 m/s (with the default
  // 1e-3 the spin chatters at a slip of +-2e-4 m/s, a period-2 cycle).
  const CliRun run = Run("simulate " + kBall + " --collision " + integrator_options +
                         " --duration 1.5 --report-interval 0.01 --quiet --out " + Path("out"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto contacts = ReadStoColumns(Path("out/contacts.sto"));
  ASSERT_TRUE(contacts.count("smc_contact.ball.force.Y")) << "no SMC columns";
  const double weight = 9.80665;
  EXPECT_NEAR(contacts.at("smc_contact.ball.force.Y").back(), weight, 1e-4 * weight);
  EXPECT_NEAR(contacts.at("smc_contact.ground.force.Y").back(), -weight, 1e-4 * weight);
  EXPECT_NEAR(contacts.at("smc_contact.ball.force.X").back(), 0.0, 1e-9);
  EXPECT_EQ(contacts.at("smc_contact.active_contacts").back(), 1.0);
  EXPECT_EQ(contacts.at("smc_contact.ground-ball.active_contacts").back(), 1.0);
  // In the air at the start: no contact.
  EXPECT_EQ(contacts.at("smc_contact.active_contacts").front(), 0.0);
  // The sphere and the floor collide: not reported as left out.
  EXPECT_EQ(run.err.find("NOT simulated"), std::string::npos) << run.err;
}

TEST_F(SimulateCollisionTest, BallSettlesOnTheFloorOnItsWeightWithSmc) {
  ExpectBallSettles("--slip-speed 0.01 --integrator euler --step 1e-4");
}

// The implicit Euler step takes the friction's slope in its Jacobian: no chatter with the
// default slip speed.
TEST_F(SimulateCollisionTest, BallSettlesOnTheFloorOnItsWeightWithImplicitEuler) {
  ExpectBallSettles("--integrator implicit-euler --step 1e-4");
}

// The same ball with NSC (the default material: friction 0.6, restitution 0.4) at the
// default step of 1e-3 s: it falls 0.2 m, bounces to e^2 of its fall and comes to rest (its
// bounces end by t = 0.2 + 2 e v / (g (1 - e)) = 0.47 s). The provider reports the sphere
// touching while it is within the envelope (2 mm) of the floor, and the sphere is not inflated
// by it, so it rests up to the envelope deep (docs/contact.md); the fall height is measured
// from that resting level. Positions are resolved to v h = 2e-3 m at the 2 m/s impact.
TEST_F(SimulateCollisionTest, BallBouncesToRestitutionSquaredAndRestsWithNsc) {
  const CliRun run = Run("simulate " + kBall + " --collision --contact nsc --duration 1.5 " +
                         "--report-interval 0.001 --quiet --out " + Path("out"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto states = ReadStoColumns(Path("out/states.sto"));
  std::string ty_label;
  for (const auto& [label, column] : states) {
    if (label.ends_with("/ty/value")) ty_label = label;
  }
  ASSERT_FALSE(ty_label.empty()) << "no ty column";
  const std::vector<double>& ty = states.at(ty_label);
  const std::vector<double>& time = states.at("time");
  const double radius = 0.1, envelope = 2e-3, e = 0.4;
  const double rest = ty.back();
  EXPECT_LE(rest, radius + 1e-9);
  EXPECT_GE(rest, radius - envelope - 1e-6);
  const std::string u_label = ty_label.substr(0, ty_label.size() - 5) + "speed";
  ASSERT_TRUE(states.count(u_label)) << u_label;
  EXPECT_NEAR(states.at(u_label).back(), 0.0, 1e-6);
  // The first apex after the first impact (which is at t = 0.2 s).
  double apex = 0.0;
  for (size_t i = 0; i < time.size(); ++i) {
    if (time[i] > 0.22 && time[i] < 0.40) apex = std::max(apex, ty[i]);
  }
  const double fall = 0.3 - rest;
  EXPECT_NEAR(apex - rest, e * e * fall, 2e-3) << "fall " << fall;
}

// NSC's contacts.sto: at rest the floor's impulse per step is m g h, so the reported force
// (impulse / h) is the weight, to the solver's tolerance (1e-6 m/s on the ball's speed at both
// ends of the step: an impulse error of at most m 2e-6 m/s, 2e-3 N at h = 1 ms), with no torque
// about the ball's centre (the contact is below it) and one active contact; before the first
// step, none.
TEST_F(SimulateCollisionTest, NscContactsTableReportsTheBallsWeightAtRest) {
  const CliRun run = Run("simulate " + kBall + " --collision --contact nsc --duration 1.5 " +
                         "--report-interval 0.01 --quiet --out " + Path("out"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto contacts = ReadStoColumns(Path("out/contacts.sto"));
  ASSERT_TRUE(contacts.count("nsc_contact.ball.force.Y")) << "no NSC columns";
  const double weight = 9.80665, bound = 1.0 * 2e-6 / 1e-3;
  EXPECT_NEAR(contacts.at("nsc_contact.ball.force.Y").back(), weight, bound);
  EXPECT_NEAR(contacts.at("nsc_contact.ground.force.Y").back(), -weight, bound);
  for (const char* axis : {"X", "Z"})
    EXPECT_NEAR(contacts.at(std::string("nsc_contact.ball.force.") + axis).back(), 0.0, bound);
  for (const char* axis : {"X", "Y", "Z"}) {
    EXPECT_NEAR(contacts.at(std::string("nsc_contact.ball.torque.") + axis).back(), 0.0,
                0.1 * bound);
  }
  EXPECT_EQ(contacts.at("nsc_contact.active_contacts").back(), 1.0);
  EXPECT_EQ(contacts.at("nsc_contact.ground-ball.active_contacts").back(), 1.0);
  EXPECT_EQ(contacts.at("nsc_contact.active_contacts").front(), 0.0);
  EXPECT_EQ(contacts.at("nsc_contact.ball.force.Y").front(), 0.0);
}

// A collision shape the model cannot have (a ContactMesh whose file is missing, a
// ContactCylinder with a negative radius) stops --collision with exit 2, file:line:component.
TEST_F(SimulateCollisionTest, BadCollisionShapesAreRefusedWithFileLineAndComponent) {
  std::ifstream in(kBall);
  std::stringstream text;
  text << in.rdbuf();
  const std::string ball = text.str();
  const std::string anchor = "<ContactSphere name=\"sphere\">";
  ASSERT_NE(ball.find(anchor), std::string::npos);
  for (const auto& [shape, what] :
       {std::pair<std::string, std::string>{
            "<ContactMesh name=\"hull\"><socket_frame>/bodyset/ball</socket_frame>"
            "<filename>missing.obj</filename></ContactMesh>\n",
            "not found"},
        {"<ContactCylinder name=\"hull\"><socket_frame>/bodyset/ball</socket_frame>"
         "<radius>-0.1</radius></ContactCylinder>\n",
         "radius > 0"}}) {
    std::string model = ball;
    model.insert(model.find(anchor), shape);
    std::ofstream(Path("bad.osim")) << model;
    const CliRun run = Run("simulate " + Path("bad.osim") + " --collision --contact nsc " +
                           "--duration 0.01 --quiet --out " + Path("out"));
    EXPECT_EQ(run.exit_code, 2) << run.err;
    EXPECT_NE(run.err.find("bad.osim:"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("/contactgeometryset/hull"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find(what), std::string::npos) << run.err;
  }
}

// A ContactMesh file that is neither beside the model nor in its Geometry/ folder is found in
// --geometry-dir, as visual meshes are; without it the error names the file, the component and
// the folders searched.
TEST_F(SimulateCollisionTest, ContactMeshIsFoundInTheGeometryDir) {
  std::ifstream in(kBall);
  std::stringstream text;
  text << in.rdbuf();
  std::string model = text.str();
  const std::string anchor = "<ContactSphere name=\"sphere\">";
  ASSERT_NE(model.find(anchor), std::string::npos);
  model.insert(model.find(anchor),
               "<ContactMesh name=\"groove\"><socket_frame>/ground</socket_frame>"
               "<filename>v_groove.obj</filename></ContactMesh>\n");
  std::ofstream(Path("groove.osim")) << model;
  const std::string meshes = std::string(SINEW_TEST_DATA_DIR) + "/sinew";
  for (const std::string contact : {"smc", "nsc"}) {
    const CliRun found =
        Run("simulate " + Path("groove.osim") + " --collision --contact " + contact +
            " --geometry-dir " + meshes + " --duration 0.01 --quiet --out " + Path("out"));
    EXPECT_EQ(found.exit_code, 0) << found.err;
  }
  const CliRun missing = Run("simulate " + Path("groove.osim") +
                             " --collision --duration 0.01 --quiet --out " + Path("out"));
  EXPECT_EQ(missing.exit_code, 2) << missing.err;
  for (const std::string& part :
       {std::string("groove.osim:"), std::string("/contactgeometryset/groove"),
        std::string("'v_groove.obj' not found"), Path("Geometry")})
    EXPECT_NE(missing.err.find(part), std::string::npos) << missing.err << "\nlacks " << part;
}

TEST_F(SimulateCollisionTest, BadContactOptionsAreRefused) {
  for (const auto& [options, what] :
       {std::pair<std::string, std::string>{"--collision --friction -0.1", "friction -0.1"},
        {"--collision --young-modulus 0", "young_modulus 0"},
        {"--collision --kn -5", "kn -5"},
        {"--ground-plane 0", "needs --collision"},
        {"--contact smc", "needs --collision"},
        {"--friction 0.3", "needs --collision"}}) {
    const CliRun run =
        Run("simulate " + kBall + " " + options + " --duration 0.1 --quiet --out " + Path("out"));
    EXPECT_EQ(run.exit_code, 2) << options << ": " << run.err;
    EXPECT_NE(run.err.find(what), std::string::npos) << options << ": " << run.err;
  }
}

}  // namespace
}  // namespace sinew

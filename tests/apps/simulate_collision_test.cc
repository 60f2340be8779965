// `sinew simulate --collision`: a ball with a ContactSphere and no contact force settles on
// the model's ContactHalfSpace through SMC (the default contact method), its contacts.sto row
// at rest carrying its weight on one contact; NSC makes it bounce and rest;
// contact options are checked (exit 2). NSC's impulse solver options reach the stepper, its
// work is reported per row in contacts.sto and summed up on stderr.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "apps/cli_test_util.h"
#include "engine/test_models.h"

namespace sinew {
namespace {

using engine::testing::ReadStoColumns;
using testing::CliRun;
using testing::ReadText;

const std::string kBall = std::string(SINEW_TEST_DATA_DIR) + "/sinew/ball_on_floor.osim";
const std::string kTable = std::string(SINEW_TEST_DATA_DIR) + "/sinew/table_on_floor.osim";

// The whole number in `text` right after `before` (-1 when `before` is not there).
long NumberAfter(const std::string& text, const std::string& before) {
  const size_t at = text.find(before);
  if (at == std::string::npos) return -1;
  return std::stol(text.substr(at + before.size()));
}

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

// With tangential springs (--kt, damped by --gt) the friction of the resting ball is a spring on
// its contact's displacement, kept from step to step, with fixed steps and with rk45's. The
// spring (k_t = kt sqrt(r d), about 4e4 N/m at the default modulus's depth) on the slip's
// effective mass (0.29 kg) is damped at about a third of critical by gt = 100 N s/m, so its
// swing after the last bounce dies out long before the end. Its period (17 ms) is near rk45's
// steps at rest, where rk45 lets rounding's sideways force grow to what its accuracy allows
// (measured: 1e-5 N at 1e-6, 4.6e-7 N at 1e-8, 8.8e-10 N at 1e-10), hence 1e-10 here.
TEST_F(SimulateCollisionTest, BallSettlesOnTheFloorOnItsWeightWithTangentialSprings) {
  ExpectBallSettles("--kt 1e7 --gt 100 --integrator euler --step 1e-4");
  ExpectBallSettles("--kt 1e7 --gt 100 --accuracy 1e-10");
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

// --nsc-iterations caps every step's impulse solve. The table lands on its four legs at once
// (four coupled contacts, so one APGD iteration cannot solve an impact) and stays on them: with
// one iteration allowed, contacts.sto's iteration column never exceeds 1, steps end above the
// tolerance and the run says so loudly, counting them as the column does. A row whose step
// ended above the tolerance (its residual column > 1e-6 m/s, the solver's own stopping test)
// counts one more unconverged step than the row before (one step per row: the report interval
// is the step).
TEST_F(SimulateCollisionTest, NscIterationLimitIsHonouredAndUnconvergedStepsAreReported) {
  const CliRun run = Run("simulate " + kTable + " --collision --contact nsc --nsc-iterations 1 " +
                         "--duration 1 --report-interval 0.001 --quiet --out " + Path("out"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto contacts = ReadStoColumns(Path("out/contacts.sto"));
  const std::vector<double>& iterations = contacts.at("nsc_contact.solver_iterations");
  const std::vector<double>& residual = contacts.at("nsc_contact.solver_residual");
  const std::vector<double>& unconverged = contacts.at("nsc_contact.unconverged_steps");
  ASSERT_EQ(iterations.size(), 1001u);
  EXPECT_EQ(*std::max_element(iterations.begin(), iterations.end()), 1.0);
  EXPECT_GE(*std::min_element(iterations.begin(), iterations.end()), 0.0);
  const double tolerance = 1e-6;  // the default
  for (size_t i = 1; i < residual.size(); ++i) {
    EXPECT_GE(unconverged[i], unconverged[i - 1]) << "row " << i;
    if (residual[i] > tolerance) {
      EXPECT_EQ(unconverged[i], unconverged[i - 1] + 1) << "row " << i;
      EXPECT_EQ(iterations[i], 1.0) << "row " << i;
    }
  }
  EXPECT_GT(unconverged.back(), 0.0);
  // The warning on stderr (even with --quiet) gives the same count.
  const std::string warning = "did NOT reach its tolerance of 1e-06 m/s in ";
  ASSERT_NE(run.err.find(warning), std::string::npos) << run.err;
  EXPECT_EQ(NumberAfter(run.err, warning), static_cast<long>(unconverged.back())) << run.err;
  EXPECT_NE(run.err.find("limit of 1 iteration "), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("--nsc-iterations"), std::string::npos) << run.err;
  // With the default limit the same scene meets the tolerance in every step (and says so).
  const CliRun full = Run("simulate " + kTable + " --collision --contact nsc --duration 1 " +
                          "--report-interval 0.001 --out " + Path("full"));
  ASSERT_EQ(full.exit_code, 0) << full.err;
  const auto full_contacts = ReadStoColumns(Path("full/contacts.sto"));
  EXPECT_EQ(full_contacts.at("nsc_contact.unconverged_steps").back(), 0.0);
  for (const double r : full_contacts.at("nsc_contact.solver_residual")) EXPECT_LE(r, tolerance);
  EXPECT_NE(full.err.find("reached its tolerance of 1e-06 m/s in all"), std::string::npos)
      << full.err;
}

// --strict means no silent approximation: an NSC run whose impulse solver left steps above its
// tolerance (one iteration allowed on the table's four coupled legs, as above) fails with exit
// code 2 and names them, after writing every output of the whole run (the tables complete,
// with the steps counted as the warning counts them, and the --export file). With the default
// limit, where every step meets the tolerance, --strict accepts the same run.
TEST_F(SimulateCollisionTest, StrictRefusesNscStepsAboveTheSolverTolerance) {
  const std::string run_options =
      " --collision --contact nsc --duration 1 --report-interval "
      "0.001 --quiet --strict --out ";
  const CliRun run = Run("simulate " + kTable + run_options + Path("out") +
                         " --nsc-iterations 1 --export " + Path("out.glb"));
  EXPECT_EQ(run.exit_code, 2) << run.err;
  const std::string error =
      "sinew: error: --strict: NSC's contact impulse solver (apgd) did NOT "
      "reach its tolerance of 1e-06 m/s in ";
  ASSERT_NE(run.err.find(error), std::string::npos) << run.err;
  EXPECT_EQ(run.err.find("sinew: warning: NSC"), std::string::npos) << run.err;  // said once
  EXPECT_NE(run.err.find("--nsc-iterations"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("output files were written"), std::string::npos) << run.err;
  const auto contacts = ReadStoColumns(Path("out/contacts.sto"));
  ASSERT_EQ(contacts.at("time").size(), 1001u);  // every row, to the end
  EXPECT_DOUBLE_EQ(contacts.at("time").back(), 1.0);
  const double unconverged = contacts.at("nsc_contact.unconverged_steps").back();
  EXPECT_GT(unconverged, 0.0);
  EXPECT_EQ(NumberAfter(run.err, error), static_cast<long>(unconverged)) << run.err;
  for (const char* file : {"out/states.sto", "out/bodies.sto", "out/forces.sto"}) {
    EXPECT_NE(ReadText(Path(file)).find("status=complete"), std::string::npos) << file;
  }
  EXPECT_GT(std::filesystem::file_size(Path("out.glb")), 0u);
  // Every step within the tolerance: --strict has nothing to refuse.
  const CliRun full = Run("simulate " + kTable + run_options + Path("full"));
  EXPECT_EQ(full.exit_code, 0) << full.err;
  EXPECT_EQ(ReadStoColumns(Path("full/contacts.sto")).at("nsc_contact.unconverged_steps").back(),
            0.0);
}

// A run stopped by SIGINT still reports the unconverged steps it took (at least those its
// partial contacts.sto counts: the report covers the steps after the last row too).
TEST_F(SimulateCollisionTest, InterruptedNscRunStillReportsUnconvergedSteps) {
  // 10^4 s at 1 ms steps cannot end in the 3 s before SIGINT arrives (see
  // SimulateOutputTest.InterruptKeepsTheRowsComputedSoFar for --foreground).
  const std::string command =
      "timeout --foreground --preserve-status -s INT 3 " + std::string(SINEW_CLI_PATH) +
      " simulate " + kTable + " --collision --contact nsc --nsc-iterations 1 --duration 1e4 " +
      "--report-interval 0.01 --quiet --out " + Path("out") + " 2>" + Path("err.txt");
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGINT);
  const std::string err = ReadText(Path("err.txt"));
  EXPECT_NE(err.find("stopped by SIGINT"), std::string::npos) << err;
  const auto contacts = ReadStoColumns(Path("out/contacts.sto"));
  const double counted = contacts.at("nsc_contact.unconverged_steps").back();
  EXPECT_GT(counted, 0.0);
  const long reported = NumberAfter(err, "did NOT reach its tolerance of 1e-06 m/s in ");
  EXPECT_GE(reported, static_cast<long>(counted)) << err;
}

// Gauss-Seidel and APGD solve the same contact law: at a tolerance of 1e-12 m/s both runs meet
// it in every step, and their body speeds agree. Each solve leaves every contact's velocity
// within the tolerance of the law's, so the two runs' contact-point velocities differ by at
// most 2 tol per step, and what a step leaves over adds at most linearly: after N steps with
// contacts, 2 tol N (m/s) for the speeds of points, that over the shortest lever from the body's
// origin to a contact (0.1 m: the ball's radius, the legs' 0.112 m about x) for the angular
// speeds. Two scenes: the ball launched sideways at 1 m/s (its landing makes it roll, it
// bounces and rests: one contact) and the table on its four legs (coupled contacts).
// --nsc-solver reaches the stepper: the note names it, and for the ball's single contact (its
// normal and tangential rows decoupled, W_tt isotropic) one Gauss-Seidel sweep is exact.
TEST_F(SimulateCollisionTest, GaussSeidelAndApgdAgreeWithinTheirTolerance) {
  std::string ball = ReadText(kBall);
  const std::string tx = "<Coordinate name=\"tx\"/>";
  ASSERT_NE(ball.find(tx), std::string::npos);
  ball.replace(ball.find(tx), tx.size(),
               "<Coordinate name=\"tx\"><default_speed_value>1</default_speed_value></Coordinate>");
  std::ofstream(Path("ball.osim")) << ball;
  const double tolerance = 1e-12, lever = 0.1;
  for (const std::string& model : {Path("ball.osim"), kTable}) {
    std::map<std::string, std::map<std::string, std::vector<double>>> states;
    long steps = 0;
    for (const std::string solver : {"apgd", "gauss-seidel"}) {
      const std::string out = Path(solver);
      const CliRun run = Run("simulate " + model + " --collision --contact nsc --nsc-solver " +
                             solver + " --nsc-iterations 10000 --nsc-tolerance 1e-12 " +
                             "--duration 1.5 --report-interval 0.01 --out " + out);
      ASSERT_EQ(run.exit_code, 0) << run.err;
      const std::string note = "solver (" + solver + ") reached its tolerance of 1e-12 m/s in all ";
      ASSERT_NE(run.err.find(note), std::string::npos) << run.err;
      steps = std::max(steps, NumberAfter(run.err, note));
      const auto contacts = ReadStoColumns(out + "/contacts.sto");
      for (const double r : contacts.at("nsc_contact.solver_residual")) EXPECT_LE(r, tolerance);
      EXPECT_EQ(contacts.at("nsc_contact.unconverged_steps").back(), 0.0);
      if (solver == "gauss-seidel" && model != kTable) {
        const auto& iterations = contacts.at("nsc_contact.solver_iterations");
        EXPECT_EQ(*std::max_element(iterations.begin(), iterations.end()), 1.0);
      }
      states[solver] = ReadStoColumns(out + "/states.sto");
    }
    ASSERT_GT(steps, 0);
    const double bound = 2.0 * tolerance * static_cast<double>(steps);
    int compared = 0;
    for (const auto& [label, apgd] : states.at("apgd")) {
      if (!label.ends_with("/speed")) continue;
      const std::vector<double>& gauss_seidel = states.at("gauss-seidel").at(label);
      ASSERT_EQ(apgd.size(), gauss_seidel.size());
      // The coordinate: "/jointset/free/<coordinate>/speed"; rx, ry and rz turn.
      const std::string path = label.substr(0, label.size() - 6);
      const bool angular = path.substr(path.rfind('/') + 1).starts_with("r");
      double largest = 0.0;
      for (size_t i = 0; i < apgd.size(); ++i)
        largest = std::max(largest, std::abs(apgd[i] - gauss_seidel[i]));
      EXPECT_LE(largest, angular ? bound / lever : bound) << model << " " << label;
      ++compared;
    }
    EXPECT_EQ(compared, 6) << model;
  }
}

TEST_F(SimulateCollisionTest, BadContactOptionsAreRefused) {
  for (const auto& [options, what] :
       {std::pair<std::string, std::string>{"--collision --friction -0.1", "friction -0.1"},
        {"--collision --young-modulus 0", "young_modulus 0"},
        {"--collision --kn -5", "kn -5"},
        {"--ground-plane 0", "needs --collision"},
        {"--contact smc", "needs --collision"},
        {"--friction 0.3", "needs --collision"},
        // NSC's stepper: bad values, and options that do not apply without --contact nsc.
        {"--collision --contact nsc --nsc-iterations 0", "whole number >= 1, not '0'"},
        {"--collision --contact nsc --nsc-iterations 2.5", "whole number >= 1, not '2.5'"},
        {"--collision --contact nsc --nsc-tolerance 0", "number > 0, not '0'"},
        {"--collision --contact nsc --nsc-tolerance -1e-6", "number > 0, not '-1e-6'"},
        {"--collision --contact nsc --nsc-solver jacobi", "jacobi"},
        {"--collision --contact nsc --nsc-max-recovery-speed -1", "number >= 0, not '-1'"},
        {"--collision --contact nsc --nsc-min-bounce-speed nan", "number >= 0, not 'nan'"},
        {"--nsc-iterations 5",
         "--nsc-iterations: sets NSC's stepper: it needs --collision "
         "--contact nsc"},
        {"--collision --nsc-tolerance 1e-8", "--nsc-tolerance: sets NSC's stepper: it needs"},
        {"--collision --contact smc --nsc-solver apgd", "--nsc-solver: sets NSC's stepper"},
        {"--contact nsc --nsc-min-bounce-speed 0.1", "needs --collision --contact nsc"}}) {
    const CliRun run =
        Run("simulate " + kBall + " " + options + " --duration 0.1 --quiet --out " + Path("out"));
    EXPECT_EQ(run.exit_code, 2) << options << ": " << run.err;
    EXPECT_NE(run.err.find(what), std::string::npos) << options << ": " << run.err;
  }
}

}  // namespace
}  // namespace sinew

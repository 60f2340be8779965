// OpenSim's bouncing-ball models (HuntCrossleyForce, ElasticFoundationForce on a mesh,
// SmoothSphereHalfSpaceForce) dropped onto their floor: they bounce, never gain energy, and
// come to rest on a contact force equal to their weight; a ball without dissipation or friction
// keeps its energy.
#include <gtest/gtest.h>
#include <sinew/contact/contact_force.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/energy.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/state.h>
#include <sinew/opensim/parser.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

#include "contact/contact_models.h"

namespace sinew::contact {
namespace {

const std::string kOpenSimTests =
    std::string(SINEW_TEST_DATA_DIR) + "/opensim-org/opensim-core/OpenSim/Simulation/Test/";

struct BallCase {
  const char* file;
  bool exact_potential;  ///< false where OpenSim's potential energy is an approximation
};

class BouncingBallTest : public ::testing::TestWithParam<BallCase> {};

TEST_P(BouncingBallTest, BouncesNeverGainsEnergyAndSettlesOnItsWeight) {
  // Each model: a 1 kg ball (inertia 1 kg m^2) on a FreeJoint, a 0.5 m sphere (or a 720-face
  // mesh of one) against the ground half-space y < 0, stiffness 1e4, dissipation 0.75 s/m,
  // friction 0.3 (static, dynamic, viscous), transition velocity 0.1 m/s, g = 9.8065 m/s^2.
  // Dropped with its centre at 1 m (0.5 m above the floor), as OpenSim's testContactGeometry.
  const BallCase& ball = GetParam();
  opensim::OpenSimParser parser;
  auto system = parser.Parse(kOpenSimTests + ball.file);
  EXPECT_TRUE(parser.GetReport().not_simulated().empty()) << ball.file;
  const ContactForce& contact = testing::FindContactForce(*system, "contact");
  engine::State state = engine::MakeDefaultState(*system);
  const std::string ty = "/jointset/" + system->joints()[0].name + "/";
  engine::SetCoordinateValue(*system, state, "ball_ty", 1.0);
  engine::IntegratorSettings settings;
  settings.accuracy = 1e-9;
  auto integrator = engine::MakeIntegrator("rk45", *system, settings);

  double energy = engine::CalcMechanicalEnergy(*system, state);
  const double energy0 = energy;
  double worst_gain = 0.0, highest_rebound_speed = 0.0;
  bool touched = false;
  for (int k = 1; k <= 5000; ++k) {
    integrator->StepTo(state, 1e-3 * k);
    const double e = engine::CalcMechanicalEnergy(*system, state);
    worst_gain = std::max(worst_gain, e - energy);
    energy = e;
    touched = touched || contact.CountActiveContacts(state) > 0;
    if (touched) {
      highest_rebound_speed =
          std::max(highest_rebound_speed, engine::GetCoordinateSpeed(*system, state, "ball_ty"));
    }
  }
  // It bounced: after the first touch it rose again.
  EXPECT_GT(highest_rebound_speed, 0.1) << ball.file;
  // Energy never rises by more than the integrator's error per millisecond (1e-9 relative
  // accuracy on states of order 1: 1e-8 J of 5 J); OpenSim's smoothed model reports an
  // approximate potential energy (2/5 f_H d, not the integral of its smoothed f_H), so there
  // the check is only that the energy falls overall.
  if (ball.exact_potential) {
    EXPECT_LT(worst_gain, 1e-7 * energy0) << ball.file;
  }
  EXPECT_LT(energy, energy0) << ball.file;

  // At rest after 5 s: the contact force on the ball is its weight, straight up, through its
  // centre (no torque), and ground takes the opposite.
  EXPECT_LT(std::abs(engine::GetCoordinateSpeed(*system, state, "ball_ty")), 1e-4) << ball.file;
  const std::vector<Vec6> loads = contact.CalcGroupLoads(state);
  const auto& groups = contact.record_groups();
  const double weight = 1.0 * 9.8065;
  for (size_t g = 0; g < groups.size(); ++g) {
    const double sign = groups[g].body == 0 ? -1.0 : 1.0;
    const Vec3 force = sign * loads[g].head<3>();
    EXPECT_NEAR(force.y(), weight, 1e-4 * weight) << ball.file << " " << groups[g].label;
    // Sideways: only the friction of the ball's residual drift (below 1e-6 m/s), which the
    // friction law makes at most weight * (2 u_s / v_t + u_v) * 1e-6 = 6e-5 N; its moment
    // about the ball's centre at most 0.5 m times that.
    EXPECT_LT(std::hypot(force.x(), force.z()), 6e-5) << ball.file;
    if (groups[g].body != 0) {
      EXPECT_LT(loads[g].tail<3>().norm(), 3e-5) << ball.file;
    }
    std::cout << ball.file << " " << groups[g].label << ": force - weight " << force.y() - weight
              << " N, sideways " << std::hypot(force.x(), force.z()) << " N, torque "
              << loads[g].tail<3>().norm() << " N m\n";
  }
  EXPECT_EQ(contact.RecordLabels(*system)[0], "contact." + groups[0].label + ".force.X");
  std::cout << ball.file << ": largest energy gain in 1 ms " << worst_gain << " J, rebound "
            << highest_rebound_speed << " m/s, energy " << energy0 << " -> " << energy << " J\n";
}

INSTANTIATE_TEST_SUITE_P(OpenSimModels, BouncingBallTest,
                         ::testing::Values(BallCase{"BouncingBall_HuntCrossley.osim", true},
                                           BallCase{"BouncingBallModelEF.osim", true},
                                           BallCase{"BouncingBall_SmoothSphereHalfSpace.osim",
                                                    false}));

TEST(HuntCrossleyTest, BallWithoutDissipationOrFrictionKeepsItsEnergy) {
  // A 1 kg ball of radius 0.1 m, stiffness 1e7 Pa, no dissipation, no friction, dropped from
  // 0.5 m: T + m g h + 2/5 f_H d is conserved, so it bounces back to its height every time.
  auto system = testing::ParseContactModel(
      testing::FreeBodyContactModel(1.0, Vec3(0.004, 0.004, 0.004), Vec3(0, -9.80665, 0), 0.1,
                                    {Vec3::Zero()},
                                    testing::HuntCrossleyText(1, 1e7, 0.0, 0.0, 0.1)),
      "elastic_ball.osim");
  engine::State state = engine::MakeDefaultState(*system);
  engine::SetCoordinateValue(*system, state, "ty", 0.6);
  engine::IntegratorSettings settings;
  settings.accuracy = 1e-10;
  auto integrator = engine::MakeIntegrator("rk45", *system, settings);
  const double energy0 = engine::CalcMechanicalEnergy(*system, state);
  const ContactForce& contact = testing::FindContactForce(*system, "contact");
  double worst = 0.0, lowest = 1.0, highest_after = 0.0;
  int contacts = 0;
  bool in_contact = false;
  for (int k = 1; k <= 20000; ++k) {
    integrator->StepTo(state, 1e-4 * k);
    worst = std::max(worst, std::abs(engine::CalcMechanicalEnergy(*system, state) - energy0));
    const bool now = contact.CountActiveContacts(state) > 0;
    contacts += now && !in_contact ? 1 : 0;
    in_contact = now;
    const double y = engine::GetCoordinateValue(*system, state, "ty");
    lowest = std::min(lowest, y);
    if (contacts > 0) highest_after = std::max(highest_after, y);
  }
  EXPECT_GE(contacts, 2);                 // 2 s hold two bounces of 0.64 s (0.5 m falls)
  EXPECT_LT(worst, 1e-7 * energy0);       // rk45 at 1e-10
  EXPECT_NEAR(highest_after, 0.6, 1e-6);  // back to its height
  // Deepest dent d: the Hertz energy 2/5 f_H d = 8/15 k sqrt(R k) d^(5/2) (k = (1e7)^(2/3) / 2
  // for two equal materials) takes the fall's m g (0.5 + d); solved by Newton's method. The
  // lowest sample (every 0.1 ms, where the ball turns at ~1300 m/s^2) is within 1e-5 m of it.
  const double k = 0.5 * std::pow(1e7, 2.0 / 3.0), c = 8.0 / 15.0 * k * std::sqrt(0.1 * k);
  const double mg = 9.80665;
  double d = 0.01;
  for (int i = 0; i < 50; ++i) {
    d -= (c * std::pow(d, 2.5) - mg * (0.5 + d)) / (2.5 * c * std::pow(d, 1.5) - mg);
  }
  EXPECT_NEAR(lowest, 0.1 - d, 1e-5);
  std::cout << "elastic ball: " << contacts << " bounces, energy error " << worst / energy0
            << " relative, apex after bounce " << highest_after << " m, lowest " << lowest
            << " m (closed form " << 0.1 - d << " m)\n";
}

}  // namespace
}  // namespace sinew::contact

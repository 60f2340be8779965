// Hunt-Crossley contact between two spheres of different materials: a ball thrown at a sphere
// fixed to ground, without gravity, dissipation or friction. Simbody's combination of the
// materials (k = k1 k2 / (k1 + k2) with k_i = stiffness_i^(2/3)) and the effective radius
// R = r1 r2 / (r1 + r2) give the deepest overlap in closed form; the ball comes back with its
// speed.
#include <gtest/gtest.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/energy.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/state.h>

#include <cmath>
#include <iostream>
#include <sstream>

#include "contact/contact_models.h"

namespace sinew::contact {
namespace {

std::string Parameters(const char* geometry, double stiffness) {
  std::ostringstream p;
  p << "<HuntCrossleyForce::ContactParameters><geometry>" << geometry << "</geometry><stiffness>"
    << stiffness << "</stiffness></HuntCrossleyForce::ContactParameters>";
  return p.str();
}

TEST(HuntCrossleySphereTest, BallRicochetsOffAFixedSphereWithTheCombinedHertzLaw) {
  constexpr double kM = 2.0, kV = 1.0, kR1 = 0.2, kR2 = 0.1, kE1 = 1e7, kE2 = 4e6;
  // The ball (r2 = 0.1 m, stiffness 4e6) starts at x = 0.35 m moving at -1 m/s towards the
  // ground's sphere (r1 = 0.2 m at the origin, stiffness 1e7).
  std::ostringstream text;
  text << R"(<OpenSimDocument Version="40000"><Model name="spheres"><gravity>0 0 0</gravity>
<Ground name="ground"/><BodySet><objects><Body name="body"><mass>)"
       << kM << R"(</mass><inertia>0.01 0.01 0.01 0 0 0</inertia></Body></objects></BodySet>
<JointSet><objects><FreeJoint name="free"><socket_parent_frame>/ground</socket_parent_frame>
<socket_child_frame>/bodyset/body</socket_child_frame><coordinates><Coordinate name="rx"/>
<Coordinate name="ry"/><Coordinate name="rz"/><Coordinate name="tx"/><Coordinate name="ty"/>
<Coordinate name="tz"/></coordinates></FreeJoint></objects></JointSet>
<ForceSet><objects><HuntCrossleyForce name="contact"><HuntCrossleyForce::ContactParametersSet>
<objects>)"
       << Parameters("fixed", kE1) << Parameters("ball", kE2)
       << R"(</objects></HuntCrossleyForce::ContactParametersSet>
</HuntCrossleyForce></objects></ForceSet>
<ContactGeometrySet><objects>
<ContactSphere name="fixed"><socket_frame>/ground</socket_frame><radius>)"
       << kR1 << R"(</radius></ContactSphere>
<ContactSphere name="ball"><socket_frame>/bodyset/body</socket_frame><radius>)"
       << kR2
       << R"(</radius></ContactSphere></objects></ContactGeometrySet></Model></OpenSimDocument>)";
  auto system = testing::ParseContactModel(text.str(), "spheres.osim");
  engine::State state = engine::MakeDefaultState(*system);
  engine::SetCoordinateValue(*system, state, "tx", 0.35);
  engine::SetCoordinateSpeed(*system, state, "tx", -kV);
  engine::IntegratorSettings settings;
  settings.accuracy = 1e-11;
  auto integrator = engine::MakeIntegrator("rk45", *system, settings);
  const double energy0 = engine::CalcMechanicalEnergy(*system, state);
  double closest = 1.0, worst_energy = 0.0;
  for (int n = 1; n <= 20000; ++n) {
    integrator->StepTo(state, 1e-5 * n);
    closest = std::min(closest, engine::GetCoordinateValue(*system, state, "tx"));
    worst_energy =
        std::max(worst_energy, std::abs(engine::CalcMechanicalEnergy(*system, state) - energy0));
  }
  // 1/2 m v^2 = 2/5 f_H d = 8/15 k sqrt(R k) d^(5/2) at the deepest overlap d.
  const double k1 = std::pow(kE1, 2.0 / 3.0), k2 = std::pow(kE2, 2.0 / 3.0);
  const double k = k1 * k2 / (k1 + k2), R = kR1 * kR2 / (kR1 + kR2);
  const double d = std::pow(0.5 * kM * kV * kV / (8.0 / 15.0 * k * std::sqrt(R * k)), 0.4);
  // Sampled every 10 us where the ball turns at ~3e3 m/s^2: within 2e-7 m of the turn.
  EXPECT_NEAR(closest, kR1 + kR2 - d, 2e-7);
  EXPECT_NEAR(engine::GetCoordinateSpeed(*system, state, "tx"), kV, 1e-8);
  EXPECT_LT(worst_energy, 1e-8 * energy0);
  std::cout << "spheres: closest " << closest << " m (closed form " << kR1 + kR2 - d
            << "), speed after " << engine::GetCoordinateSpeed(*system, state, "tx")
            << " m/s, energy error " << worst_energy << " J\n";
}

TEST(ElasticFoundationSphereTest, MeshBallSettlesOnAGroundSphereOnItsWeight) {
  // sphere.obj (BouncingBallModelEF's 720-face ball of radius 0.5 m) on a 1 kg body, dropped
  // onto a ContactSphere of radius 5 m fixed to ground (top at y = 0); ElasticFoundationForce
  // with stiffness 1e4, dissipation 0.75, no friction. At rest the springs carry the weight.
  const std::string mesh = std::string(SINEW_TEST_DATA_DIR) +
                           "/opensim-org/opensim-core/OpenSim/Simulation/Test/sphere.obj";
  const std::string text = R"(<OpenSimDocument Version="40000"><Model name="ef">
<gravity>0 -9.8065 0</gravity><Ground name="ground"/><BodySet><objects><Body name="ball">
<mass>1</mass><inertia>1 1 1 0 0 0</inertia></Body></objects></BodySet>
<JointSet><objects><FreeJoint name="free"><socket_parent_frame>/ground</socket_parent_frame>
<socket_child_frame>/bodyset/ball</socket_child_frame><coordinates><Coordinate name="rx"/>
<Coordinate name="ry"/><Coordinate name="rz"/><Coordinate name="tx"/><Coordinate name="ty"/>
<Coordinate name="tz"/></coordinates></FreeJoint></objects></JointSet>
<ForceSet><objects><ElasticFoundationForce name="contact">
<ElasticFoundationForce::ContactParametersSet><objects><ElasticFoundationForce::ContactParameters>
<geometry>mesh dome</geometry><stiffness>10000</stiffness><dissipation>0.75</dissipation>
</ElasticFoundationForce::ContactParameters></objects></ElasticFoundationForce::ContactParametersSet>
</ElasticFoundationForce></objects></ForceSet>
<ContactGeometrySet><objects>
<ContactSphere name="dome"><socket_frame>/ground</socket_frame><location>0 -5 0</location>
<radius>5</radius></ContactSphere>
<ContactMesh name="mesh"><socket_frame>/bodyset/ball</socket_frame><filename>)" +
                           mesh + R"(</filename></ContactMesh>
</objects></ContactGeometrySet></Model></OpenSimDocument>)";
  auto system = testing::ParseContactModel(text, "ef_on_sphere.osim");
  const ContactForce& contact = testing::FindContactForce(*system, "contact");
  engine::State state = engine::MakeDefaultState(*system);
  engine::SetCoordinateValue(*system, state, "ty", 0.6);
  engine::IntegratorSettings settings;
  settings.accuracy = 1e-8;
  auto integrator = engine::MakeIntegrator("rk45", *system, settings);
  integrator->StepTo(state, 8.0);
  const std::vector<Vec6> loads = contact.CalcGroupLoads(state);
  ASSERT_EQ(contact.record_groups()[0].label, "ball");
  EXPECT_NEAR(loads[0][1], 9.8065, 1e-4 * 9.8065);
  EXPECT_LT(std::abs(engine::GetCoordinateSpeed(*system, state, "ty")), 1e-5);
  EXPECT_GT(contact.CountActiveContacts(state), 0);
  std::cout << "mesh on sphere: force " << loads[0][1] << " N on "
            << contact.CountActiveContacts(state) << " springs, ball at "
            << engine::GetCoordinateValue(*system, state, "ty") << " m\n";
}

}  // namespace
}  // namespace sinew::contact

// opensim-models' bouncing_block.osim: a block whose two-link leg lands its heel sphere on a
// HuntCrossleyForce platform (stiffness 1e8, dissipation 0.5 s/m, friction 0.9/0.9/0.6), with a
// spring, a bushing, a coordinate limit and two PointOnLineConstraints. Dissipation, friction
// and the bushing's damping only take energy: the mechanical energy (springs and contact
// included) never rises, and the heel never sinks through the platform.
#include <gtest/gtest.h>
#include <sinew/contact/contact_force.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/energy.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/state.h>
#include <sinew/opensim/parser.h>

#include <algorithm>
#include <iostream>
#include <string>

#include "contact/contact_models.h"

namespace sinew::contact {
namespace {

TEST(BouncingBlockTest, LandsOnItsHeelWithoutGainingEnergyOrSinkingThrough) {
  opensim::OpenSimParser parser;
  auto system =
      parser.Parse(std::string(SINEW_TEST_DATA_DIR) +
                   "/opensim-org/opensim-models/Models/BouncingBlock/bouncing_block.osim");
  EXPECT_TRUE(parser.GetReport().not_simulated().empty());
  const ContactForce& contact = testing::FindContactForce(*system, "foot_contact_force");
  const int link2 = system->FindBody("link2");
  engine::State state = engine::MakeDefaultState(*system);
  engine::IntegratorSettings settings;
  settings.accuracy = 1e-8;
  auto integrator = engine::MakeIntegrator("rk45", *system, settings);
  double energy = engine::CalcMechanicalEnergy(*system, state);
  const double energy0 = energy;
  double worst_gain = 0.0, lowest_heel = 1.0, peak_force = 0.0;
  int touches = 0;
  bool touching = false;
  for (int k = 1; k <= 2000; ++k) {
    integrator->StepTo(state, 1e-3 * k);
    const double e = engine::CalcMechanicalEnergy(*system, state);
    worst_gain = std::max(worst_gain, e - energy);
    energy = e;
    const bool now = contact.CountActiveContacts(state) > 0;
    touches += now && !touching ? 1 : 0;
    touching = now;
    // The heel sphere (radius 5 cm) is centred on link2's origin; the platform is y < 0.
    lowest_heel = std::min(lowest_heel, state.bodies[link2].p_GB.y() - 0.05);
    for (const Vec6& load : contact.CalcGroupLoads(state))
      peak_force = std::max(peak_force, load.head<3>().norm());
  }
  EXPECT_GE(touches, 1);
  // The energy may rise only by the integrator's error between samples (1e-8 relative on
  // states of order 1, energies of order 100 J).
  EXPECT_LT(worst_gain, 1e-5);
  EXPECT_LT(energy, energy0);
  // The heel never goes deeper than the Hertz dent under the largest contact force seen,
  // d = (F / (4/3 k sqrt(r k)))^(2/3), k = (1e8)^(2/3)/2 (an upper bound: while it sinks,
  // dissipation adds to the elastic force).
  const double k = 0.5 * std::pow(1e8, 2.0 / 3.0);
  const double dent = std::pow(peak_force / (4.0 / 3.0 * k * std::sqrt(0.05 * k)), 2.0 / 3.0);
  EXPECT_GT(lowest_heel, -dent * 1.01);
  std::cout << "bouncing_block: " << touches << " touches, peak contact force " << peak_force
            << " N, deepest heel " << -lowest_heel << " m (Hertz dent at the peak " << dent
            << " m), largest energy gain " << worst_gain << " J, energy " << energy0 << " -> "
            << energy << " J\n";
}

}  // namespace
}  // namespace sinew::contact

// The Delassus blocks of NSC contact on Rajagopal2015 (the skeleton-on-ground scene of issue
// 14): its two patella CoordinateCouplerConstraints are solved by the Schur complement, and
// KktSolver::SolveUnitLoadResponses (the tree paths between the bodies and ground plus the
// Schur correction) must give what six full KKT solves per loaded body give, to rounding.
#include "engine/unit_load_responses.h"

#include <gtest/gtest.h>
#include <sinew/engine/kkt.h>
#include <sinew/engine/nsc_integrator.h>

#include <vector>

#include "contact/skeleton_on_ground.h"

namespace sinew::contact {
namespace {

TEST(UnitLoadResponsesTest, Rajagopal2015WithPatellaCouplersEqualsFullSolves) {
  testing::SkeletonOnGround scene = testing::MakeSkeletonOnGround(0.05);
  const engine::System& system = *scene.system;
  std::vector<int> bodies;
  for (int b = 1; b < system.num_bodies(); ++b) bodies.push_back(b);
  // Target sets: every body; the bodies the cylinders touch the floor with in the resting
  // scene, in another order and with a repeat; a patella alone (a coupled joint's body).
  const std::vector<int> feet = {system.FindBody("calcn_l"), system.FindBody("toes_r"),
                                 system.FindBody("pelvis"), system.FindBody("calcn_l")};
  const std::vector<int> patella = {system.FindBody("patella_r")};
  for (int b : feet) ASSERT_GT(b, 0);
  ASSERT_GT(patella[0], 0);
  // At the default pose and at a generic one, mid-fall after the impact (0.2 s of NSC steps).
  engine::NscIntegrator integrator(system, scene.provider, {.step = 1e-3});
  for (double t : {0.0, 0.2}) {
    if (t > 0.0) integrator.StepTo(scene.state, t);
    engine::KktSolver kkt(system);
    kkt.Factorize(scene.state);
    ASSERT_EQ(kkt.num_extra_equations(), 2);  // the two patella couplers
    for (int source : bodies) {
      const char* name = system.bodies()[source].name.c_str();
      EXPECT_LT(engine::testing::UnitLoadResponseError(kkt, source, bodies), 1e-12)
          << name << " t = " << t;
      EXPECT_LT(engine::testing::UnitLoadResponseError(kkt, source, feet), 1e-12)
          << name << " t = " << t;
      EXPECT_LT(engine::testing::UnitLoadResponseError(kkt, source, patella), 1e-12)
          << name << " t = " << t;
    }
  }
}

}  // namespace
}  // namespace sinew::contact

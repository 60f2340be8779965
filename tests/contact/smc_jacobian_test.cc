// SMC's analytic load Jacobians (SmoothCollisionForce::CalcLoadJacobians, what implicit-euler
// uses instead of differencing the contact force) against central finite differences of the
// force itself (engine::CalcForceJacobiansByFiniteDifference, step 1e-6).
#include <gtest/gtest.h>
#include <sinew/contact/smooth_collision_force.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/force_jacobian.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/kkt.h>

#include <iostream>

#include "contact/contact_models.h"
#include "contact/skeleton_drop.h"

namespace sinew::contact {
namespace {

struct Jacobians {
  MatX K_analytic, D_analytic, K_differenced, D_differenced;
};

// Both forms of the Jacobians of `system`'s only force element (the SMC contact) at `state`.
Jacobians CalcBoth(const engine::System& system, const engine::State& state) {
  EXPECT_EQ(system.force_elements().size(), 1u);
  engine::KktSolver kkt(system);
  kkt.Factorize(state);
  const std::vector<int> columns = engine::CalcSupportColumns(system, kkt, 0);
  const int n = static_cast<int>(columns.size());
  Jacobians j;
  engine::CalcForceJacobiansByFiniteDifference(system, kkt, state, 0, columns, j.K_differenced,
                                               j.D_differenced);
  j.K_analytic = MatX::Zero(n, n);
  j.D_analytic = MatX::Zero(n, n);
  EXPECT_TRUE(system.force_elements()[0]->CalcLoadJacobians(system.MakeForceContext(0, state),
                                                            j.K_analytic, j.D_analytic));
  return j;
}

double RelativeDifference(const MatX& a, const MatX& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

// The skeleton dropped on the floor, at the landing, collapsing and lying (semi-implicit Euler
// at 0.25 ms): landing, sliding and resting contacts on the floor and between limbs. D is
// exact: each contact's force depends on the velocities only through the relative velocity at
// its point, so it must equal the differences to their truncation error, about
// (step / v_s)^2 = (1e-6 / 1e-3)^2 = 1e-6 of the largest entry with the default slip speed.
TEST(SmcLoadJacobiansTest, VelocityJacobianOfTheDroppedSkeletonEqualsFiniteDifferences) {
  const testing::SkeletonDrop scene = testing::MakeSkeletonDrop(0.05);
  const engine::System& system = *scene.system;
  engine::State state = engine::MakeDefaultState(system);
  engine::IntegratorSettings settings;
  settings.step = 2.5e-4;
  auto integrator = engine::MakeIntegrator("euler", system, settings);
  for (const double t : {0.12, 0.3, 1.0}) {
    integrator->StepTo(state, t);
    const Jacobians j = CalcBoth(system, state);
    ASSERT_GT(j.D_differenced.cwiseAbs().maxCoeff(), 0.0) << "t = " << t;  // in contact
    const double d_error = RelativeDifference(j.D_analytic, j.D_differenced);
    EXPECT_LT(d_error, 1e-6) << "t = " << t;
    std::cout << "t = " << t << " s: D within " << d_error << " of the differences' largest entry"
              << " (K, which leaves out how the contacts' points and levers move, within "
              << RelativeDifference(j.K_analytic, j.K_differenced) << ")\n";
  }
}

// A ball resting on the floor at its Hertz depth, still: its contact point stays under its
// centre whatever the ball does to first order (it turns about the centre; moved, the point
// moves with it), its lever is along the normal and there is no slip, so the terms K leaves
// out vanish and both K and D must equal the differences to their truncation error. For K
// that is the central difference's on f ~ d^(3/2), step^2 f''' / (6 f') = step^2 / (24 d^2)
// (2.9e-4 here: the depth is only 12 um); for D 1e-6, as above.
TEST(SmcLoadJacobiansTest, BallAtRestOnTheFloorHasTheDifferencedJacobians) {
  constexpr double kM = 1.0, kR = 0.1, kG = 9.80665;
  CollisionMaterial material;
  material.young_modulus = 1e9;
  opensim::OpenSimParser parser;
  parser.EnableCollision();
  parser.SetContactMethod(ContactMethod::kSmc);
  parser.SetContactMaterial(material);
  const model::ModelSpec spec =
      io::ReadOsimString(testing::FreeBodyContactModel(kM, Vec3::Constant(0.4 * kM * kR * kR),
                                                       Vec3(0, -kG, 0), kR, {Vec3::Zero()}, ""),
                         "resting_ball.osim");
  engine::System system(spec.gravity);
  parser.ParseSpec(system, spec);
  system.Finalize();
  const double modulus =
      material.young_modulus / (2.0 * (1.0 - material.poisson_ratio * material.poisson_ratio));
  const double depth = std::pow(kM * kG / (4.0 / 3.0 * modulus * std::sqrt(kR)), 2.0 / 3.0);
  engine::State state = engine::MakeDefaultState(system);
  engine::SetCoordinateValue(system, state, "ty", kR - depth);
  const Jacobians j = CalcBoth(system, state);
  // The normal stiffness 3/2 f / d along y on the ball's translation.
  const double stiffness = 1.5 * kM * kG / depth;
  EXPECT_NEAR(-j.K_analytic(4, 4), stiffness, 1e-9 * stiffness);
  constexpr double kStep = 1e-6;  // CalcForceJacobiansByFiniteDifference's, m
  const double truncation = kStep * kStep / (24.0 * depth * depth);
  const double k_error = RelativeDifference(j.K_analytic, j.K_differenced);
  EXPECT_LT(k_error, 1.05 * truncation);
  EXPECT_GT(k_error, 0.95 * truncation);  // the difference is the truncation, nothing else
  std::cout << "ball at rest: K within " << k_error << " of the differences (their truncation "
            << truncation << ")\n";
  EXPECT_LT(RelativeDifference(j.D_analytic, j.D_differenced), 1e-6);
}

}  // namespace
}  // namespace sinew::contact

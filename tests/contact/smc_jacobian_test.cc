// SMC's analytic load Jacobians (SmoothCollisionForce::CalcLoadJacobians, what implicit-euler
// uses instead of differencing the contact force) against central finite differences of the
// force itself (engine::CalcForceJacobiansByFiniteDifference, step 1e-6).
#include <gtest/gtest.h>
#include <sinew/contact/smooth_collision_force.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/force_jacobian.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/kkt.h>

#include <cmath>
#include <initializer_list>
#include <iostream>
#include <memory>

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
// With tangential springs (kt = 1e7 Pa, gt = 20 N s/m) the friction is linear in the velocity
// while a spring holds and u f_n along the trial force while it slips, whose differences are
// as close (at 0.36 s instead of 0.3 s: it lands again a little later).
void ExpectDroppedSkeletonVelocityJacobians(const CollisionMaterial& material,
                                            std::initializer_list<double> times) {
  const testing::SkeletonDrop scene = testing::MakeSkeletonDrop(0.05, material);
  const engine::System& system = *scene.system;
  engine::State state = engine::MakeDefaultState(system);
  engine::IntegratorSettings settings;
  settings.step = 2.5e-4;
  auto integrator = engine::MakeIntegrator("euler", system, settings);
  for (const double t : times) {
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

TEST(SmcLoadJacobiansTest, VelocityJacobianOfTheDroppedSkeletonEqualsFiniteDifferences) {
  ExpectDroppedSkeletonVelocityJacobians({}, {0.12, 0.3, 1.0});
}

TEST(SmcLoadJacobiansTest, VelocityJacobianWithTangentialSpringsEqualsFiniteDifferences) {
  CollisionMaterial material;
  material.kt = 1e7;
  material.gt = 20.0;
  ExpectDroppedSkeletonVelocityJacobians(material, {0.12, 0.36, 1.0});
}

constexpr double kM = 1.0, kR = 0.1, kG = 9.80665;

// A 1 kg ball of radius 0.1 m (the model's ContactSphere on the floor, SMC with `material`)
// resting still at its Hertz depth.
struct RestingBall {
  engine::System system{Vec3(0, -kG, 0)};
  engine::State state;
  double depth = 0.0;
};

std::unique_ptr<RestingBall> MakeRestingBall(const CollisionMaterial& material) {
  auto ball = std::make_unique<RestingBall>();
  opensim::OpenSimParser parser;
  parser.EnableCollision();
  parser.SetContactMethod(ContactMethod::kSmc);
  parser.SetContactMaterial(material);
  const model::ModelSpec spec =
      io::ReadOsimString(testing::FreeBodyContactModel(kM, Vec3::Constant(0.4 * kM * kR * kR),
                                                       Vec3(0, -kG, 0), kR, {Vec3::Zero()}, ""),
                         "resting_ball.osim");
  parser.ParseSpec(ball->system, spec);
  ball->system.Finalize();
  const double modulus =
      material.young_modulus / (2.0 * (1.0 - material.poisson_ratio * material.poisson_ratio));
  ball->depth = std::pow(kM * kG / (4.0 / 3.0 * modulus * std::sqrt(kR)), 2.0 / 3.0);
  ball->state = engine::MakeDefaultState(ball->system);
  engine::SetCoordinateValue(ball->system, ball->state, "ty", kR - ball->depth);
  return ball;
}

// A ball resting on the floor at its Hertz depth, still: its contact point stays under its
// centre whatever the ball does to first order (it turns about the centre; moved, the point
// moves with it), its lever is along the normal and there is no slip, so the terms K leaves
// out vanish and both K and D must equal the differences to their truncation error. For K
// that is the central difference's on f ~ d^(3/2), step^2 f''' / (6 f') = step^2 / (24 d^2)
// (2.9e-4 here: the depth is only 12 um); for D 1e-6, as above. Returns K.
MatX ExpectRestingBallJacobians(const RestingBall& ball) {
  const Jacobians j = CalcBoth(ball.system, ball.state);
  // The normal stiffness 3/2 f / d along y on the ball's translation.
  const double stiffness = 1.5 * kM * kG / ball.depth;
  EXPECT_NEAR(-j.K_analytic(4, 4), stiffness, 1e-9 * stiffness);
  constexpr double kStep = 1e-6;  // CalcForceJacobiansByFiniteDifference's, m
  const double truncation = kStep * kStep / (24.0 * ball.depth * ball.depth);
  const double k_error = RelativeDifference(j.K_analytic, j.K_differenced);
  EXPECT_LT(k_error, 1.05 * truncation);
  EXPECT_GT(k_error, 0.95 * truncation);  // the difference is the truncation, nothing else
  std::cout << "ball at rest: K within " << k_error << " of the differences (their truncation "
            << truncation << ")\n";
  EXPECT_LT(RelativeDifference(j.D_analytic, j.D_differenced), 1e-6);
  return j.K_analytic;
}

TEST(SmcLoadJacobiansTest, BallAtRestOnTheFloorHasTheDifferencedJacobians) {
  CollisionMaterial material;
  material.young_modulus = 1e9;
  ExpectRestingBallJacobians(*MakeRestingBall(material));
}

// The same with a tangential spring (kt = 1e8 Pa, gt = 5 N s/m), its history made at the
// resting state: moving the ball sideways by dx stretches the spring by dx (the floor's point
// stays, the ball's moves with it), a force -k_t dx with k_t = kt sqrt(r d); the differences
// of that linear force are exact, so K and D still differ from them by the normal's
// truncation alone.
TEST(SmcLoadJacobiansTest, BallAtRestWithATangentialSpringHasTheDifferencedJacobians) {
  CollisionMaterial material;
  material.young_modulus = 1e9;
  material.kt = 1e8;
  material.gt = 5.0;
  auto ball = MakeRestingBall(material);
  ball->system.UpdateDiscreteData(ball->state);
  ASSERT_EQ(ball->state.discrete.size(), 1u);
  const MatX K = ExpectRestingBallJacobians(*ball);
  const double k_t = material.kt * std::sqrt(kR * ball->depth);
  EXPECT_NEAR(-K(3, 3), k_t, 1e-9 * k_t);
  EXPECT_NEAR(-K(5, 5), k_t, 1e-9 * k_t);
}

}  // namespace
}  // namespace sinew::contact

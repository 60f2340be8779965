// SpringGeneralizedForce, PointToPointSpring and CoordinateLimitForce against closed forms and
// hand computations of OpenSim's formulas.
#include <gtest/gtest.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/energy.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/loads.h>
#include <sinew/engine/system.h>
#include <sinew/forces/coordinate_limit_force.h>
#include <sinew/forces/point_to_point_spring.h>
#include <sinew/forces/spring_generalized_force.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>

#include "engine/test_models.h"

namespace sinew::forces {
namespace {

using engine::testing::Coord;
using engine::testing::MakeBody;

TEST(SpringGeneralizedForceTest, SliderOscillatesAsTheClosedForm) {
  // m x'' = -k (x - L) - c x' with c = 0: x - L = x0 cos(sqrt(k/m) t). Gravity is across the
  // slider (along -y), so it does no work.
  constexpr double kM = 2.0, kK = 50.0, kRest = 0.3, kX0 = 0.1;
  engine::System system(Vec3(0, -9.80665, 0));
  const int b = system.AddBody(MakeBody("block", kM, Vec3::Zero(), 0.01 * Mat3::Identity()));
  system.AddJoint("slide", 0, Transform(), b, Transform(), engine::JointForm::kParameterized,
                  std::make_shared<engine::testing::SliderModel>(), {Coord("x", kRest + kX0)});
  system.AddForceElement(std::make_shared<SpringGeneralizedForce>("spring", 0, kK, kRest, 0.0));
  system.Finalize();
  engine::IntegratorSettings settings;
  settings.accuracy = 1e-12;
  auto integrator = engine::MakeIntegrator("rk45", system, settings);
  engine::State state = engine::MakeDefaultState(system);
  const double e0 = engine::CalcMechanicalEnergy(system, state);
  EXPECT_NEAR(e0, 0.5 * kK * kX0 * kX0, 1e-15);  // the spring's potential energy
  const double w = std::sqrt(kK / kM);
  double worst = 0.0;
  for (int k = 1; k <= 60; ++k) {  // 3 s, about 2.4 periods
    const double t = 0.05 * k;
    integrator->StepTo(state, t);
    worst = std::max(worst, std::abs(state.q[0] - kRest - kX0 * std::cos(w * t)));
  }
  EXPECT_LT(worst, 1e-7);
  EXPECT_NEAR(engine::CalcMechanicalEnergy(system, state), e0,
              integrator->stats().steps * settings.accuracy);
  std::cout << "spring slider: worst error " << worst << " m in " << integrator->stats().steps
            << " steps\n";
}

TEST(SpringGeneralizedForceTest, ForceAndJacobianFollowOpenSimsFormula) {
  engine::System system(Vec3::Zero());
  const int b = system.AddBody(MakeBody("block", 1.0, Vec3::Zero(), 0.01 * Mat3::Identity()));
  system.AddJoint("slide", 0, Transform(), b, Transform(), engine::JointForm::kParameterized,
                  std::make_shared<engine::testing::SliderModel>(), {Coord("x", 0.5, -0.3)});
  const auto spring = std::make_shared<SpringGeneralizedForce>("spring", 0, 20.0, 0.2, 3.0);
  system.AddForceElement(spring);
  system.Finalize();
  const engine::State state = engine::MakeDefaultState(system);
  const engine::ForceContext context = system.MakeForceContext(0, state);
  // -20 (0.5 - 0.2) - 3 (-0.3) = -6 + 0.9.
  EXPECT_NEAR(spring->CalcForce(context), -5.1, 1e-14);
  MatX K(1, 1), D(1, 1);
  ASSERT_TRUE(spring->CalcLoadJacobians(context, K, D));
  EXPECT_EQ(K(0, 0), -20.0);
  EXPECT_EQ(D(0, 0), -3.0);
  // Its power is f u = (-5.1)(-0.3).
  EXPECT_NEAR(engine::CalcForcePower(system, state, 0), 1.53, 1e-14);
}

TEST(PointToPointSpringTest, PendulumOnASpringConservesEnergy) {
  // A 1 kg bob on a pin 1 m below the pivot, pulled towards a ground point by a spring of
  // rest length 0.3 m; it swings under gravity and the spring. Energy T + V_gravity + V_spring
  // is constant; rk45 at accuracy A changes it by at most ~A (energy scale 10 J) per step.
  engine::System system(Vec3(0, -9.80665, 0));
  const int bob = system.AddBody(MakeBody("bob", 1.0, Vec3(0, -1, 0), 1e-3 * Mat3::Identity()));
  system.AddJoint("pin", 0, Transform(), bob, Transform(), engine::JointForm::kParameterized,
                  std::make_shared<engine::testing::RevoluteModel>(Vec3::UnitZ()),
                  {Coord("theta", 1.0, 0.0)});
  const auto spring = std::make_shared<PointToPointSpring>("spring", 0, Vec3(0.8, -0.6, 0), bob,
                                                           Vec3(0, -1, 0), 15.0, 0.3);
  system.AddForceElement(spring);
  system.Finalize();
  engine::IntegratorSettings settings;
  settings.accuracy = 1e-10;
  auto integrator = engine::MakeIntegrator("rk45", system, settings);
  engine::State state = engine::MakeDefaultState(system);
  const double e0 = engine::CalcMechanicalEnergy(system, state);
  // The spring's energy at the start: |(sin 1, -cos 1) - (0.8, -0.6)| - 0.3, by hand.
  const double d0 = std::hypot(std::sin(1.0) - 0.8, -std::cos(1.0) + 0.6);
  EXPECT_NEAR(spring->CalcPotentialEnergy(system.MakeForceContext(0, state)),
              0.5 * 15.0 * (d0 - 0.3) * (d0 - 0.3), 1e-14);
  double worst = 0.0, spring_min = 1e9, spring_max = 0.0;
  for (int k = 1; k <= 40; ++k) {
    integrator->StepTo(state, 0.05 * k);
    worst = std::max(worst, std::abs(engine::CalcMechanicalEnergy(system, state) - e0));
    const double v = spring->CalcPotentialEnergy(system.MakeForceContext(0, state));
    spring_min = std::min(spring_min, v);
    spring_max = std::max(spring_max, v);
  }
  const double steps = static_cast<double>(integrator->stats().steps);
  EXPECT_LT(worst, steps * settings.accuracy * 10.0);
  EXPECT_GT(spring_max - spring_min, 0.1);  // the spring did exchange energy
  std::cout << "pendulum + spring: energy drift " << worst << " J over " << steps << " steps\n";
}

TEST(PointToPointSpringTest, PulledPointsGetOppositeForcesAlongTheLine) {
  engine::System system(Vec3::Zero());
  const int a = system.AddBody(MakeBody("a", 1.0, Vec3::Zero(), Mat3::Identity()));
  system.AddJoint("free_a", 0, Transform(), a, Transform(), engine::JointForm::kParameterized,
                  std::make_shared<engine::testing::SliderModel>(), {Coord("x", 2.0)});
  system.AddForceElement(
      std::make_shared<PointToPointSpring>("s", 0, Vec3::Zero(), a, Vec3(0, 0.5, 0), 10.0, 1.0));
  system.Finalize();
  const engine::State state = engine::MakeDefaultState(system);
  engine::Loads loads(system.num_bodies(), system.num_coordinates());
  system.force_elements()[0]->AddLoads(system.MakeForceContext(0, state), loads);
  // Points (0,0,0) on ground and (2, 0.5, 0) on a: d = sqrt(4.25), tension 10 (d - 1),
  // force on a towards ground, with its moment about a's origin from the 0.5 m arm.
  const double d = std::sqrt(4.25), tension = 10.0 * (d - 1.0);
  const Vec3 f = -tension * Vec3(2, 0.5, 0) / d;
  EXPECT_LT((loads.body[a].tail<3>() - f).norm(), 1e-13);
  EXPECT_LT((loads.body[a].head<3>() - Vec3(0, 0.5, 0).cross(f)).norm(), 1e-13);
}

// A rotational coordinate with OpenSim's units: limits 30 deg / -20 deg, band 5 deg,
// stiffness 2 / 3 N m per degree, damping 0.05 N m s per degree.
CoordinateLimitForce MakeKneeLimit() {
  CoordinateLimitParameters p;
  p.upper_limit = 30.0;
  p.lower_limit = -20.0;
  p.transition = 5.0;
  p.upper_stiffness = 2.0;
  p.lower_stiffness = 3.0;
  p.damping = 0.05;
  return CoordinateLimitForce("limit", 0, true, p);
}

TEST(CoordinateLimitForceTest, ValuesAreOpenSimsFormulaByHand) {
  const CoordinateLimitForce limit = MakeKneeLimit();
  const double deg = M_PI / 180.0;
  // Inside the range: nothing, whatever the speed.
  EXPECT_EQ(limit.CalcForce(10 * deg, 2.0), 0.0);
  EXPECT_EQ(limit.CalcPotentialEnergy(10 * deg), 0.0);
  // 2 deg into the 5 deg band above 30 deg: x = 0.4, s = 10 x^3 - 15 x^4 + 6 x^5 = 0.31744;
  // stiffness 2 N m/deg = 2 / deg N m/rad; f = -s 2/deg (2 deg) = -4 s N m.
  const double s = 10 * 0.064 - 15 * 0.0256 + 6 * 0.01024;
  ASSERT_NEAR(s, 0.31744, 1e-15);
  EXPECT_NEAR(limit.CalcForce(32 * deg, 0.0), -4.0 * s, 1e-12);
  // Damping there: -(0.05 / deg) s u.
  EXPECT_NEAR(limit.CalcForce(32 * deg, 0.5) - limit.CalcForce(32 * deg, 0.0),
              -0.05 / deg * s * 0.5, 1e-12);
  // Energy in the band: K dq^2 x^5 (2 - 2.5 x + 6/7 x^2) with K dq^2 = (2/deg)(5 deg)^2.
  const double x = 0.4;
  EXPECT_NEAR(limit.CalcPotentialEnergy(32 * deg),
              2.0 / deg * 25 * deg * deg * std::pow(x, 5) * (2 - 2.5 * x + 6.0 / 7.0 * x * x),
              1e-14);
  // 10 deg past the upper limit (beyond the band): full stiffness, f = -2 N m/deg x 10 deg.
  EXPECT_NEAR(limit.CalcForce(40 * deg, 0.0), -20.0, 1e-12);
  EXPECT_NEAR(limit.CalcForce(40 * deg, -1.0), -20.0 + 0.05 / deg, 1e-12);
  EXPECT_NEAR(limit.CalcPotentialEnergy(40 * deg), 2.0 / deg * (0.5 * 100 - 25.0 / 7.0) * deg * deg,
              1e-13);
  // 7 deg below the lower limit: +3 N m/deg x 7 deg pushes back up.
  EXPECT_NEAR(limit.CalcForce(-27 * deg, 0.0), 21.0, 1e-12);
  // 1 deg into the lower band: x = 0.2.
  const double s2 = 10 * 0.008 - 15 * 0.0016 + 6 * 0.00032;
  EXPECT_NEAR(limit.CalcForce(-21 * deg, 0.0), 3.0 * s2, 1e-12);
}

TEST(CoordinateLimitForceTest, EnergyIsTheStiffnessIntegralAndDampingDissipates) {
  const CoordinateLimitForce limit = MakeKneeLimit();
  const double deg = M_PI / 180.0;
  const double h = 1e-6;
  for (double q_deg : {-30.0, -24.0, -22.5, -20.5, 0.0, 30.5, 31.0, 33.0, 34.9, 36.0, 50.0}) {
    const double q = q_deg * deg;
    // -dV/dq is the stiffness part of the force (central difference, error ~h^2 V''').
    const double dV =
        (limit.CalcPotentialEnergy(q + h) - limit.CalcPotentialEnergy(q - h)) / (2 * h);
    EXPECT_NEAR(-dV, limit.CalcForce(q, 0.0), 1e-6) << q_deg;
    // Damping power is never positive, and negative wherever a limit acts.
    for (double u : {-2.0, 0.7}) {
      const double damping_power = (limit.CalcForce(q, u) - limit.CalcForce(q, 0.0)) * u;
      EXPECT_LE(damping_power, 0.0) << q_deg;
      if (limit.CalcPotentialEnergy(q) > 0.0) {
        EXPECT_LT(damping_power, 0.0) << q_deg;
      }
    }
  }
}

TEST(CoordinateLimitForceTest, AnalyticJacobianEqualsFiniteDifferences) {
  engine::System system(Vec3::Zero());
  const int b = system.AddBody(MakeBody("b", 1.0, Vec3::Zero(), 0.1 * Mat3::Identity()));
  system.AddJoint("pin", 0, Transform(), b, Transform(), engine::JointForm::kParameterized,
                  std::make_shared<engine::testing::RevoluteModel>(Vec3::UnitZ()),
                  {Coord("q", 0.0, 0.0)});
  const auto limit = std::make_shared<CoordinateLimitForce>(MakeKneeLimit());
  system.AddForceElement(limit);
  system.Finalize();
  const double deg = M_PI / 180.0, h = 1e-7;
  for (double q_deg : {-22.0, 10.0, 32.0, 40.0}) {
    engine::State state = engine::MakeDefaultState(system);
    state.q[0] = q_deg * deg;
    state.u[0] = 0.8;
    MatX K(1, 1), D(1, 1);
    ASSERT_TRUE(limit->CalcLoadJacobians(system.MakeForceContext(0, state), K, D));
    const double q = state.q[0], u = state.u[0];
    EXPECT_NEAR(K(0, 0), (limit->CalcForce(q + h, u) - limit->CalcForce(q - h, u)) / (2 * h),
                1e-5 * (1 + std::abs(K(0, 0))))
        << q_deg;
    EXPECT_NEAR(D(0, 0), (limit->CalcForce(q, u + h) - limit->CalcForce(q, u - h)) / (2 * h),
                1e-6 * (1 + std::abs(D(0, 0))))
        << q_deg;
  }
}

TEST(CoordinateLimitForceTest, TranslationalCoordinateUsesSIUnits) {
  CoordinateLimitParameters p;
  p.upper_limit = 0.1;
  p.lower_limit = -0.1;
  p.transition = 0.01;
  p.upper_stiffness = 1000.0;
  p.lower_stiffness = 1000.0;
  const CoordinateLimitForce limit("slide_limit", 0, false, p);
  EXPECT_NEAR(limit.CalcForce(0.13, 0.0), -1000.0 * 0.03, 1e-10);
}

}  // namespace
}  // namespace sinew::forces

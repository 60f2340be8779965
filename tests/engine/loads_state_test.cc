// Applied loads (frames and points as documented), saving/restoring states, several systems in
// one process, and the fixed-step semi-implicit Euler scheme's first-order convergence.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/dynamics.h>
#include <sinew/engine/energy.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/reactions.h>
#include <sinew/engine/system.h>

#include <cmath>
#include <memory>

#include "engine/test_models.h"

namespace sinew::engine {
namespace {

using testing::Coord;
using testing::MakeBody;
using testing::RevoluteModel;

// A rod hanging from a pin about z at the ground origin, its body frame at the pivot and its
// mass centre 0.5 m down the body's -y axis.
System MakeRod(JointForm form) {
  System system(Vec3(0, -9.81, 0));
  const int rod = system.AddBody(MakeBody("rod", 2.0, Vec3(0, -0.5, 0), 0.02 * Mat3::Identity()));
  system.AddJoint("pin", 0, Transform::Identity(), rod, Transform::Identity(), form,
                  std::make_shared<RevoluteModel>(Vec3::UnitZ()), {Coord("q", 0.8)});
  system.Finalize();
  return system;
}

TEST(LoadsTest, LoadsThatBalanceGravityGiveNoAcceleration) {
  const double gravity_torque = 2.0 * 9.81 * 0.5 * std::sin(0.8);  // restoring, about -z
  for (JointForm form : {JointForm::kParameterized, JointForm::kPin}) {
    const System system = MakeRod(form);
    const State state = MakeDefaultState(system);
    Data data(system);
    const double free_fall = CalcAccelerations(system, state, nullptr, data).vdot.head<3>().norm();
    EXPECT_NEAR(free_fall, gravity_torque / (0.02 + 2.0 * 0.25), 1e-12);
    // Generalized force on the coordinate.
    Loads generalized(system.num_bodies(), system.num_coordinates());
    generalized.AddGeneralizedForce(0, gravity_torque);
    // Torque on the body about G's z.
    Loads torque(system.num_bodies(), system.num_coordinates());
    torque.AddTorque(1, Vec3(0, 0, gravity_torque));
    // Torque between ground and the body.
    Loads between(system.num_bodies(), system.num_coordinates());
    between.AddTorqueBetween(0, 1, Vec3(0, 0, gravity_torque));
    // The weight cancelled by an upward force at the mass centre (point given in B).
    Loads lift(system.num_bodies(), system.num_coordinates());
    lift.AddForceAtPoint(state, 1, Vec3(0, -0.5, 0), Vec3(0, 2.0 * 9.81, 0));
    // A horizontal force at the rod's end (1 m down B's -y): torque_z = cos(q) f_x.
    Loads push(system.num_bodies(), system.num_coordinates());
    push.AddForceAtPoint(state, 1, Vec3(0, -1.0, 0), Vec3(gravity_torque / std::cos(0.8), 0, 0));
    for (const Loads* loads : {&generalized, &torque, &between, &lift, &push}) {
      const Accelerations a = CalcAccelerations(system, state, loads, data);
      EXPECT_LT(a.vdot.lpNorm<Eigen::Infinity>(), 1e-12);
    }
  }
}

TEST(StateTest, SavedStatesRestartIdenticallyAndSystemsAreIndependent) {
  const System a = MakeRod(JointForm::kParameterized);
  const System b = MakeRod(JointForm::kPin);
  State sa = MakeDefaultState(a), sb = MakeDefaultState(b);
  IntegratorSettings settings;
  settings.accuracy = 1e-9;
  // Interleave the two systems in one process.
  auto ia = MakeIntegrator("rk45", a, settings);
  auto ib = MakeIntegrator("rk45", b, settings);
  ia->StepTo(sa, 0.5);
  ib->StepTo(sb, 0.5);
  const State saved = sa;
  auto first = MakeIntegrator("rk45", a, settings);
  first->StepTo(sa, 1.0);
  State restored = saved;
  auto second = MakeIntegrator("rk45", a, settings);
  second->StepTo(restored, 1.0);
  EXPECT_EQ(restored.q[0], sa.q[0]);
  EXPECT_EQ(restored.u[0], sa.u[0]);
  EXPECT_EQ(restored.bodies[1].p_GB, sa.bodies[1].p_GB);
  ib->StepTo(sb, 1.0);
  EXPECT_NEAR(sb.q[0], sa.q[0], 1e-7);
  EXPECT_EQ(saved.t, 0.5);
}

TEST(StateTest, CoordinatesAreReadAndSetByName) {
  const System system = MakeRod(JointForm::kPin);
  State state = MakeDefaultState(system);
  EXPECT_DOUBLE_EQ(GetCoordinateValue(system, state, "q"), 0.8);
  SetCoordinateValue(system, state, "q", -0.3);
  SetCoordinateSpeed(system, state, "q", 1.5);
  EXPECT_NEAR(state.bodies[1].w_GB.z(), 1.5, 1e-15);
  UpdateDirectCoordinates(system, state);
  EXPECT_NEAR(GetCoordinateValue(system, state, "q"), -0.3, 1e-15);
  EXPECT_NEAR(GetCoordinateSpeed(system, state, "q"), 1.5, 1e-15);
  EXPECT_THROW(GetCoordinateValue(system, state, "nope"), Error);
}

// Semi-implicit Euler is first order: halving the step halves the error at t = 1 s.
TEST(EulerTest, FixedStepSchemeConvergesAtFirstOrder) {
  const System system = MakeRod(JointForm::kParameterized);
  State reference = MakeDefaultState(system);
  IntegratorSettings tight;
  tight.accuracy = 1e-11;
  MakeIntegrator("rk45", system, tight)->StepTo(reference, 1.0);
  double errors[2];
  for (int k = 0; k < 2; ++k) {
    IntegratorSettings settings;
    settings.step = k == 0 ? 2e-3 : 1e-3;
    State state = MakeDefaultState(system);
    auto euler = MakeIntegrator("euler", system, settings);
    euler->StepTo(state, 1.0);
    errors[k] = std::abs(state.q[0] - reference.q[0]);
    EXPECT_EQ(euler->stats().steps, k == 0 ? 500 : 1000);
  }
  EXPECT_LT(errors[1], 1e-2);
  EXPECT_NEAR(errors[0] / errors[1], 2.0, 0.3);
}

TEST(EulerTest, FixedStepSchemeKeepsEnergyBounded) {
  const System system = MakeRod(JointForm::kPin);
  State state = MakeDefaultState(system);
  const double e0 = CalcMechanicalEnergy(system, state);
  IntegratorSettings settings;
  settings.step = 1e-3;
  auto euler = MakeIntegrator("euler", system, settings);
  double max_drift = 0.0;
  for (int i = 1; i <= 100; ++i) {
    euler->StepTo(state, 0.1 * i);
    max_drift = std::max(max_drift, std::abs(CalcMechanicalEnergy(system, state) - e0));
  }
  // Symplectic: the energy error oscillates with amplitude O(h) but does not grow over 10 s.
  EXPECT_LT(max_drift / std::abs(e0), 1e-2);
}

}  // namespace
}  // namespace sinew::engine

namespace sinew::engine {
namespace {

TEST(StateTest, AStateOfAnotherSystemIsRefused) {
  const System one = MakeRod(JointForm::kPin);
  System two(Vec3(0, -9.81, 0));
  const int a = two.AddBody(testing::MakeBody("a", 1.0, Vec3(0, -0.5, 0), 0.01 * Mat3::Identity()));
  const int b = two.AddBody(testing::MakeBody("b", 1.0, Vec3(0, -0.5, 0), 0.01 * Mat3::Identity()));
  two.AddJoint("p1", 0, Transform::Identity(), a, Transform::Identity(), JointForm::kPin, nullptr,
               {testing::Coord("q1")});
  two.AddJoint("p2", a, Transform::Translation(Vec3(0, -1, 0)), b, Transform::Identity(),
               JointForm::kPin, nullptr, {testing::Coord("q2")});
  two.Finalize();
  State state = MakeDefaultState(two);
  IntegratorSettings settings;
  EXPECT_THROW(MakeIntegrator("rk45", one, settings)->StepTo(state, 0.1), Error);
  EXPECT_THROW(PlaceBodies(one, state), Error);
}

}  // namespace
}  // namespace sinew::engine

namespace sinew::engine {
namespace {

// Generalized forces on Ball and Universal coordinates act the same on the direct forms (as
// torques along H's columns) as on the parameterized ones (on the joint speeds).
TEST(LoadsTest, GeneralizedForcesOnDirectAndParameterizedJointsAgree) {
  const Body body =
      testing::MakeBody("b", 1.3, Vec3(0.1, -0.4, 0.2), Mat3(Vec3(0.02, 0.03, 0.04).asDiagonal()));
  const Transform X_PF(Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()).toRotationMatrix(),
                       Vec3(0.1, 0.2, 0.3));
  for (JointForm form : {JointForm::kBall, JointForm::kUniversal}) {
    Eigen::VectorXd vdot[2];
    for (int k = 0; k < 2; ++k) {
      System system(Vec3(0, -9.81, 0));
      const int b = system.AddBody(body);
      std::shared_ptr<const kinematics::JointModel> model;
      std::vector<CoordinateDesc> coordinates{testing::Coord("a", 0.3, 0.5),
                                              testing::Coord("b", -0.2, 0.7)};
      if (form == JointForm::kBall) {
        model = std::make_shared<testing::BallModel>();
        coordinates.push_back(testing::Coord("c", 0.4, -0.3));
      } else {
        model = std::make_shared<testing::UniversalModel>();
      }
      system.AddJoint("j", 0, X_PF, b, Transform::Identity(),
                      k == 0 ? JointForm::kParameterized : form, model, coordinates);
      system.Finalize();
      const State state = MakeDefaultState(system);
      Loads loads(system.num_bodies(), system.num_coordinates());
      for (int c = 0; c < system.num_coordinates(); ++c) loads.AddGeneralizedForce(c, 1.0 + c);
      Data data(system);
      vdot[k] = CalcAccelerations(system, state, &loads, data).vdot.head<6>();
    }
    EXPECT_LT((vdot[0] - vdot[1]).norm(), 1e-12 * (1 + vdot[0].norm()));
  }
}

}  // namespace
}  // namespace sinew::engine

namespace sinew::engine {
namespace {

// A rod (pivot at its frame origin, mass centre 0.5 m down) passing through the bottom with
// angular speed w: the pin pulls it up with m (g + w^2 l) and no torque about the pivot.
TEST(LoadsTest, PinReactionAtTheBottomOfTheSwing) {
  for (JointForm form : {JointForm::kParameterized, JointForm::kPin}) {
    const System system = MakeRod(form);
    State state = MakeDefaultState(system);
    SetCoordinateValue(system, state, "q", 0.0);
    SetCoordinateSpeed(system, state, "q", 3.0);
    Data data(system);
    const Accelerations a = CalcAccelerations(system, state, nullptr, data);
    const SpatialVec reaction = CalcJointReaction(system, state, a, data.kkt, 0);
    EXPECT_NEAR(reaction[4], 2.0 * (9.81 + 9.0 * 0.5), 1e-10);
    EXPECT_NEAR(reaction[3], 0.0, 1e-10);
    EXPECT_NEAR(reaction[5], 0.0, 1e-10);
    EXPECT_LT(reaction.head<3>().norm(), 1e-10);
  }
}

}  // namespace
}  // namespace sinew::engine

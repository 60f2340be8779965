// Initial speeds and analytic motions: a spinning ball joint, a rolling (coupled) joint, a
// torque-free asymmetric body, locked and prescribed coordinates, a massless intermediate body.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/energy.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/pose.h>
#include <sinew/engine/system.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "engine/test_models.h"

namespace sinew::engine {
namespace {

using testing::BallModel;
using testing::Coord;
using testing::MakeBody;
using testing::RevoluteModel;
using testing::RollingModel;

// f(t) = a sin(w t) with derivatives.
class SineFunction final : public functions::Function {
 public:
  SineFunction(double a, double w) : a_(a), w_(w) {}
  std::string TypeName() const override { return "Sine"; }
  double Calc(double t) const override { return a_ * std::sin(w_ * t); }
  double CalcDerivative(double t, int order) const override {
    if (order == 1) return a_ * w_ * std::cos(w_ * t);
    if (order == 2) return -a_ * w_ * w_ * std::sin(w_ * t);
    return Calc(t);
  }

 private:
  double a_, w_;
};

Mat3 Exp(const Vec3& theta) { return QuatFromRotationVector(theta).toRotationMatrix(); }

IntegratorSettings Tight() {
  IntegratorSettings s;
  s.accuracy = 1e-10;
  return s;
}

// A ball joint whose F is tilted on ground; a body with isotropic inertia and its mass centre
// at the joint centre spins at the constant w_FM_F = u: R_FM(t) = exp(u t) R_FM(0).
TEST(MotionTest, BallJointSpinsWithItsDefaultSpeeds) {
  const Vec3 w(0.3, -0.5, 0.9);
  const Transform X_PF(Exp(Vec3(0.2, 0.4, -0.1)), Vec3(0.1, 1.0, 0.0));
  const Transform X_BM = Transform::Translation(Vec3(0, 0.3, 0));
  for (JointForm form : {JointForm::kParameterized, JointForm::kBall}) {
    System system;
    const int b = system.AddBody(MakeBody("ball", 2.0, Vec3(0, 0.3, 0), 0.1 * Mat3::Identity()));
    system.AddJoint("ball", 0, X_PF, b, X_BM, form, std::make_shared<BallModel>(),
                    {Coord("b1", 0.1, w.x()), Coord("b2", -0.2, w.y()), Coord("b3", 0.3, w.z())});
    system.Finalize();
    State state = MakeDefaultState(system);
    // Initial body velocity follows from the default speeds.
    EXPECT_TRUE(state.bodies[b].w_GB.isApprox(X_PF.R * w, 1e-14));
    const Mat3 R_FM0 = (X_PF.Inverse() * PoseOf(state.bodies[b]) * X_BM).R;
    auto integrator = MakeIntegrator("rk45", system, Tight());
    for (double t : {0.25, 0.5, 1.0}) {
      integrator->StepTo(state, t);
      const Mat3 R_FM = (X_PF.Inverse() * PoseOf(state.bodies[b]) * X_BM).R;
      EXPECT_LT((R_FM - Exp(w * t) * R_FM0).norm(), 1e-8) << "t=" << t;
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(state.u[i], w[i], 1e-8);
      // The mass centre stays at the joint centre.
      EXPECT_LT((PoseOf(state.bodies[b]) * Vec3(0, 0.3, 0) - X_PF.p).norm(), 1e-10);
    }
  }
}

// A CustomJoint-like coupled joint: rotation q about z and translation 0.2 q along x (a wheel
// rolling). Mass centre on the rolling axis: q(t) = q0 + u0 t exactly.
TEST(MotionTest, CoupledJointStartsWithTheRightVelocitiesAndRollsUniformly) {
  const double a = 0.2, q0 = 0.3, u0 = 2.0;
  System system;
  const int b =
      system.AddBody(MakeBody("wheel", 3.0, Vec3::Zero(), Mat3(Vec3(0.1, 0.1, 0.05).asDiagonal())));
  system.AddJoint("roll", 0, Transform::Identity(), b, Transform::Identity(),
                  JointForm::kParameterized, std::make_shared<RollingModel>(a),
                  {Coord("q", q0, u0)});
  system.Finalize();
  State state = MakeDefaultState(system);
  EXPECT_TRUE(state.bodies[b].w_GB.isApprox(Vec3(0, 0, u0)));
  EXPECT_TRUE(state.bodies[b].v_GB.isApprox(Vec3(a * u0, 0, 0)));
  EXPECT_NEAR(state.bodies[b].p_GB.x(), a * q0, 1e-15);
  auto integrator = MakeIntegrator("rk45", system, Tight());
  integrator->StepTo(state, 1.5);
  EXPECT_NEAR(state.q[0], q0 + u0 * 1.5, 1e-9);
  EXPECT_NEAR(state.u[0], u0, 1e-9);
  EXPECT_NEAR(state.bodies[b].p_GB.x(), a * (q0 + u0 * 1.5), 1e-9);
}

// A torque-free asymmetric body on a ball joint at its mass centre: kinetic energy and the
// angular momentum in G are conserved.
TEST(MotionTest, TorqueFreeAsymmetricBodyConservesMomentum) {
  for (JointForm form : {JointForm::kParameterized, JointForm::kBall}) {
    System system(Vec3(0, -9.81, 0));
    const Mat3 I = Vec3(0.1, 0.2, 0.3).asDiagonal();
    const int b = system.AddBody(MakeBody("top", 1.0, Vec3::Zero(), I));
    system.AddJoint("ball", 0, Transform::Identity(), b, Transform::Identity(), form,
                    std::make_shared<BallModel>(),
                    {Coord("x", 0, 0.1), Coord("y", 0, 2.0), Coord("z", 0, 0.2)});
    system.Finalize();
    State state = MakeDefaultState(system);
    auto momentum = [&](const State& s) {
      const Mat3 R = PoseOf(s.bodies[b]).R;
      return Vec3(R * I * R.transpose() * s.bodies[b].w_GB);
    };
    const Vec3 H0 = momentum(state);
    const double T0 = CalcKineticEnergy(system, state);
    auto integrator = MakeIntegrator("rk45", system, Tight());
    integrator->StepTo(state, 1.0);  // stays away from the Euler angles' gimbal lock
    EXPECT_LT((momentum(state) - H0).norm() / H0.norm(), 1e-8);
    EXPECT_NEAR(CalcKineticEnergy(system, state) / T0, 1.0, 1e-8);
    // The intermediate axis is unstable: the motion is far from a steady spin.
    EXPECT_GT((state.bodies[b].w_GB - Vec3(0.1, 2.0, 0.2)).norm(), 0.1);
  }
}

// Two rods (as DoublePendulum3D) with pin2 locked at 0.7 rad swing as one compound pendulum.
TEST(MotionTest, LockedCoordinateMakesACompoundPendulum) {
  System system(Vec3(0, -9.80665, 0));
  const Mat3 I = 0.025 * Mat3::Identity();
  const Transform X_BM = Transform::Translation(Vec3(0, 0.5, 0));
  const int rod1 = system.AddBody(MakeBody("rod1", 0.75, Vec3::Zero(), I));
  const int rod2 = system.AddBody(MakeBody("rod2", 1.25, Vec3::Zero(), I));
  system.AddJoint("pin1", 0, Transform::Identity(), rod1, X_BM, JointForm::kParameterized,
                  std::make_shared<RevoluteModel>(Vec3::UnitZ()), {Coord("r1_z", 0.9)});
  CoordinateDesc locked = Coord("r2_x", 0.7, 0.0);
  locked.motion = CoordinateMotion::kLocked;
  system.AddJoint("pin2", rod1, Transform::Identity(), rod2, X_BM, JointForm::kParameterized,
                  std::make_shared<RevoluteModel>(Vec3::UnitX()), {locked});
  system.Finalize();
  // Rod 2's mass centre is d2 = 0.5 + 0.5 cos(0.7) from the z axis through the pivot.
  const double d2 = 0.5 + 0.5 * std::cos(0.7);
  const double inertia = 0.025 + 0.75 * 0.25 + 0.025 + 1.25 * d2 * d2;
  const double k = 9.80665 * (0.75 * 0.5 + 1.25 * d2) / inertia;
  double theta = 0.9, omega = 0.0;
  State state = MakeDefaultState(system);
  auto integrator = MakeIntegrator("rk45", system, Tight());
  const double h = 1e-4;
  auto f = [k](double th) { return -k * std::sin(th); };
  for (int i = 1; i <= 20000; ++i) {
    const double k1 = omega, l1 = f(theta);
    const double k2 = omega + 0.5 * h * l1, l2 = f(theta + 0.5 * h * k1);
    const double k3 = omega + 0.5 * h * l2, l4a = f(theta + 0.5 * h * k2);
    const double k4 = omega + h * l4a, l4 = f(theta + h * k3);
    theta += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    omega += h / 6 * (l1 + 2 * l2 + 2 * l4a + l4);
    if (i % 2000 == 0) {
      integrator->StepTo(state, i * h);
      EXPECT_NEAR(state.q[0], theta, 1e-8);
      EXPECT_NEAR(state.q[1], 0.7, 1e-11);
      EXPECT_NEAR(state.u[1], 0.0, 1e-11);
    }
  }
}

TEST(MotionTest, PrescribedCoordinateFollowsItsFunction) {
  System system(Vec3(0, -9.80665, 0));
  const Mat3 I = 0.025 * Mat3::Identity();
  const Transform X_BM = Transform::Translation(Vec3(0, 0.5, 0));
  const int rod1 = system.AddBody(MakeBody("rod1", 0.75, Vec3::Zero(), I));
  const int rod2 = system.AddBody(MakeBody("rod2", 1.25, Vec3::Zero(), I));
  system.AddJoint("pin1", 0, Transform::Identity(), rod1, X_BM, JointForm::kParameterized,
                  std::make_shared<RevoluteModel>(Vec3::UnitZ()), {Coord("r1_z", 0.5)});
  CoordinateDesc prescribed = Coord("r2_x");
  prescribed.motion = CoordinateMotion::kPrescribed;
  prescribed.prescribed = std::make_shared<SineFunction>(0.4, 3.0);
  system.AddJoint("pin2", rod1, Transform::Identity(), rod2, X_BM, JointForm::kParameterized,
                  std::make_shared<RevoluteModel>(Vec3::UnitX()), {prescribed});
  system.Finalize();
  State state = MakeDefaultState(system);
  EXPECT_NEAR(state.u[1], 1.2, 1e-15);
  auto integrator = MakeIntegrator("rk45", system, Tight());
  for (int i = 1; i <= 10; ++i) {
    integrator->StepTo(state, 0.1 * i);
    EXPECT_NEAR(state.q[1], 0.4 * std::sin(0.3 * i), 1e-11);
    EXPECT_NEAR(state.u[1], 1.2 * std::cos(0.3 * i), 1e-10);
  }
}

// A massless body between two pins (x, then y) is a universal joint: same motion as the
// direct Universal form. The body mass matrix is singular; the constrained system is not.
TEST(MotionTest, MasslessIntermediateBodyEqualsUniversalJoint) {
  const Mat3 I = Vec3(0.02, 0.03, 0.04).asDiagonal();
  const Vec3 p_BCm(0.05, -0.4, 0.02);
  System chain(Vec3(0, -9.81, 0));
  const int cross = chain.AddBody(MakeBody("cross", 0.0, Vec3::Zero(), Mat3::Zero()));
  const int b1 = chain.AddBody(MakeBody("arm", 1.5, p_BCm, I));
  chain.AddJoint("px", 0, Transform::Identity(), cross, Transform::Identity(),
                 JointForm::kParameterized, std::make_shared<RevoluteModel>(Vec3::UnitX()),
                 {Coord("a", 0.4, 1.0)});
  chain.AddJoint("py", cross, Transform::Identity(), b1, Transform::Identity(),
                 JointForm::kParameterized, std::make_shared<RevoluteModel>(Vec3::UnitY()),
                 {Coord("b", -0.3, 0.5)});
  chain.Finalize();
  System universal(Vec3(0, -9.81, 0));
  const int b2 = universal.AddBody(MakeBody("arm", 1.5, p_BCm, I));
  universal.AddJoint("u", 0, Transform::Identity(), b2, Transform::Identity(),
                     JointForm::kUniversal, nullptr, {Coord("a", 0.4, 1.0), Coord("b", -0.3, 0.5)});
  universal.Finalize();
  State s1 = MakeDefaultState(chain), s2 = MakeDefaultState(universal);
  EXPECT_LT((s1.bodies[b1].w_GB - s2.bodies[b2].w_GB).norm(), 1e-14);
  auto i1 = MakeIntegrator("rk45", chain, Tight());
  auto i2 = MakeIntegrator("rk45", universal, Tight());
  for (double t : {0.5, 1.0, 2.0}) {
    i1->StepTo(s1, t);
    i2->StepTo(s2, t);
    EXPECT_NEAR(s1.q[0], s2.q[0], 1e-8);
    EXPECT_NEAR(s1.q[1], s2.q[1], 1e-8);
    EXPECT_NEAR(s1.u[1], s2.u[1], 1e-7);
    EXPECT_LT((s1.bodies[b1].p_GB - s2.bodies[b2].p_GB).norm(), 1e-8);
  }
}

TEST(MotionTest, SingularSystemsGiveClearErrors) {
  // Every body massless: rejected when finalized.
  System empty;
  const int b = empty.AddBody(MakeBody("ghost", 0.0, Vec3::Zero(), Mat3::Zero()));
  empty.AddJoint("pin", 0, Transform::Identity(), b, Transform::Identity(), JointForm::kPin,
                 nullptr, {Coord("q")});
  EXPECT_THROW(empty.Finalize(), Error);
  // A massless body at the end of a chain that can still turn: singular equations.
  System tip(Vec3(0, -9.81, 0));
  const int rod = tip.AddBody(MakeBody("rod", 1.0, Vec3(0, -0.5, 0), 0.01 * Mat3::Identity()));
  const int flag = tip.AddBody(MakeBody("flag", 0.0, Vec3::Zero(), Mat3::Zero()));
  tip.AddJoint("pin1", 0, Transform::Identity(), rod, Transform::Identity(), JointForm::kPin,
               nullptr, {Coord("q1", 0.3)});
  tip.AddJoint("pin2", rod, Transform::Translation(Vec3(0, -1, 0)), flag, Transform::Identity(),
               JointForm::kPin, nullptr, {Coord("q2")});
  tip.Finalize();
  State state = MakeDefaultState(tip);
  auto integrator = MakeIntegrator("rk45", tip, Tight());
  try {
    integrator->StepTo(state, 0.1);
    FAIL() << "expected a singular-system error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("singular"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sinew::engine

namespace sinew::engine {
namespace {

// A rod on a free joint and, closing a loop, on a pin to ground: the pin is a loop constraint
// (not a tree joint) and the rod must swing exactly like the rod of a plain pin.
TEST(MotionTest, LoopJointClosesAFreeJointIntoAPin) {
  const Body rod = testing::MakeBody("rod", 2.0, Vec3(0, -0.5, 0), 0.02 * Mat3::Identity());
  System loop(Vec3(0, -9.81, 0));
  const int b1 = loop.AddBody(rod);
  std::vector<CoordinateDesc> free_coordinates;
  for (const char* name : {"rx", "ry", "rz", "tx", "ty", "tz"}) {
    free_coordinates.push_back(testing::Coord(name));
  }
  free_coordinates[2].default_value = 0.8;  // consistent with the pin angle
  loop.AddJoint("free", 0, Transform::Identity(), b1, Transform::Identity(),
                JointForm::kParameterized, std::make_shared<testing::FreeModel>(),
                free_coordinates);
  loop.AddJoint("pin", 0, Transform::Identity(), b1, Transform::Identity(), JointForm::kPin,
                nullptr, {testing::Coord("q", 0.8)});
  loop.Finalize();
  EXPECT_TRUE(loop.IsLoop(1));
  System tree(Vec3(0, -9.81, 0));
  const int b2 = tree.AddBody(rod);
  tree.AddJoint("pin", 0, Transform::Identity(), b2, Transform::Identity(), JointForm::kPin,
                nullptr, {testing::Coord("q", 0.8)});
  tree.Finalize();
  State s1 = MakeDefaultState(loop), s2 = MakeDefaultState(tree);
  auto i1 = MakeIntegrator("rk45", loop, Tight());
  auto i2 = MakeIntegrator("rk45", tree, Tight());
  for (double t : {0.5, 1.0, 2.0}) {
    i1->StepTo(s1, t);
    i2->StepTo(s2, t);
    EXPECT_NEAR(s1.q[6], s2.q[0], 1e-8);  // the loop pin's angle, read off the poses
    EXPECT_NEAR(s1.q[2], s2.q[0], 1e-8);  // the free joint's z rotation
    EXPECT_LT((s1.bodies[b1].p_GB - s2.bodies[b2].p_GB).norm(), 1e-8);
    EXPECT_LT((s1.bodies[b1].w_GB - s2.bodies[b2].w_GB).norm(), 1e-7);
  }
}

}  // namespace
}  // namespace sinew::engine

namespace sinew::engine {
namespace {

// A Ball joint (speeds = angular velocity, so qdot != u) with its middle angle locked: the
// angle stays put and, the lock being workless, energy is conserved.
TEST(MotionTest, LockedBallAngleStaysAndConservesEnergy) {
  System system(Vec3(0, -9.81, 0));
  const int b = system.AddBody(testing::MakeBody("bob", 1.5, Vec3(0.1, -0.4, 0.05),
                                                 Mat3(Vec3(0.02, 0.01, 0.03).asDiagonal())));
  CoordinateDesc locked = testing::Coord("b2", 0.3);
  locked.motion = CoordinateMotion::kLocked;
  system.AddJoint("ball", 0, Transform::Identity(), b, Transform::Identity(),
                  JointForm::kParameterized, std::make_shared<testing::BallModel>(),
                  {testing::Coord("b1", 0.4), locked, testing::Coord("b3", -0.2)});
  system.Finalize();
  State state = MakeDefaultState(system);
  // Angle rates 1.0 and 0.7 for b1, b3 with b2 fixed: u = E(q) qdot.
  const Mat3 Rx = Eigen::AngleAxisd(0.4, Vec3::UnitX()).toRotationMatrix();
  const Mat3 Ry = Eigen::AngleAxisd(0.3, Vec3::UnitY()).toRotationMatrix();
  const Vec3 w = 1.0 * Vec3::UnitX() + 0.7 * (Rx * Ry * Vec3::UnitZ());
  state.u << w.x(), w.y(), w.z();
  PlaceBodies(system, state);
  const double e0 = CalcMechanicalEnergy(system, state);
  auto integrator = MakeIntegrator("rk45", system, Tight());
  for (double t : {0.5, 1.0, 2.0}) {
    integrator->StepTo(state, t);
    EXPECT_NEAR(state.q[1], 0.3, 1e-10);
    EXPECT_NEAR(CalcMechanicalEnergy(system, state), e0, 1e-8 * std::abs(e0));
  }
  EXPECT_GT(std::abs(state.q[0] - 0.4), 0.05);  // it moved
}

}  // namespace
}  // namespace sinew::engine

namespace sinew::engine {
namespace {

// A planar parallelogram four-bar of direct pins: the loop-closing pin repeats two of the
// tree's out-of-plane conditions (redundant constraints). The coupler translates without
// turning, so theta'' = -g (2 m l_c + m_c L) sin(theta) / (2 I_pivot + m_c L^2).
TEST(MotionTest, ParallelogramFourBarWithRedundantLoopPin) {
  const double m = 1.0, I = 0.01, mc = 2.0, L = 1.0, g = 9.81, theta0 = 0.6;
  System system(Vec3(0, -g, 0));
  const Body crank = testing::MakeBody("crank", m, Vec3(0, -0.5, 0), I * Mat3::Identity());
  const int c1 = system.AddBody(crank);
  const int c2 = system.AddBody(crank);
  const int coupler =
      system.AddBody(testing::MakeBody("coupler", mc, Vec3(0.5, 0, 0), 0.02 * Mat3::Identity()));
  const Transform tip = Transform::Translation(Vec3(0, -L, 0));
  system.AddJoint("p1", 0, Transform::Identity(), c1, Transform::Identity(), JointForm::kPin,
                  nullptr, {testing::Coord("q1", theta0)});
  system.AddJoint("p2", 0, Transform::Translation(Vec3(1, 0, 0)), c2, Transform::Identity(),
                  JointForm::kPin, nullptr, {testing::Coord("q2", theta0)});
  system.AddJoint("p3", c1, tip, coupler, Transform::Identity(), JointForm::kPin, nullptr,
                  {testing::Coord("q3", -theta0)});
  system.AddJoint("p4", c2, tip, coupler, Transform::Translation(Vec3(1, 0, 0)), JointForm::kPin,
                  nullptr, {testing::Coord("q4", -theta0)});
  system.Finalize();
  ASSERT_TRUE(system.IsLoop(3));
  State state = MakeDefaultState(system);
  const double k = g * (2 * m * 0.5 + mc * L) / (2 * (I + m * 0.25) + mc * L * L);
  double theta = theta0, omega = 0.0;
  auto f = [k](double th) { return -k * std::sin(th); };
  const double h = 1e-4;
  auto integrator = MakeIntegrator("rk45", system, Tight());
  for (int i = 1; i <= 15000; ++i) {
    const double k1 = omega, l1 = f(theta);
    const double k2 = omega + 0.5 * h * l1, l2 = f(theta + 0.5 * h * k1);
    const double k3 = omega + 0.5 * h * l2, l3 = f(theta + 0.5 * h * k2);
    const double k4 = omega + h * l3, l4 = f(theta + h * k3);
    theta += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    omega += h / 6 * (l1 + 2 * l2 + 2 * l3 + l4);
    if (i % 3000 == 0) {
      integrator->StepTo(state, i * h);
      EXPECT_NEAR(state.q[0], theta, 1e-8);
      EXPECT_NEAR(state.q[1], theta, 1e-8);
      EXPECT_NEAR(state.q[2], -theta, 1e-8);
      EXPECT_NEAR(state.u[0], omega, 1e-7);
    }
  }
}

}  // namespace
}  // namespace sinew::engine

// An extra constraint added with System::AddConstraint: a lever coupling two sliders,
// x1 = r x2, under gravity along the sliders. Checked against the closed form of the coupled
// motion and of the coupling force, and for its residual along the simulation.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/constraint.h>
#include <sinew/engine/dynamics.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/kkt.h>
#include <sinew/engine/system.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "engine/test_models.h"
#include "engine/unit_load_responses.h"

namespace sinew::engine {
namespace {

using testing::Coord;
using testing::MakeBody;
using testing::SliderModel;

using testing::LeverConstraint;

constexpr double kG = 9.80665;
constexpr double kM1 = 2.0, kM2 = 0.5, kRatio = 3.0;

// Two bodies on sliders along ground x (1 m apart in y), gravity along -x, coupled by
// x1 = 3 x2 through AddConstraint. Start: x2 = 0.1 m, u2 = 0.2 m/s (x1, u1 consistent).
// With `levers` = 2 the same lever is added twice (a redundant constraint).
std::unique_ptr<System> MakeLever(int levers = 1) {
  auto system = std::make_unique<System>(Vec3(-kG, 0, 0));
  const Mat3 I = 0.01 * Mat3::Identity();
  const int b1 = system->AddBody(MakeBody("b1", kM1, Vec3::Zero(), I));
  const int b2 = system->AddBody(MakeBody("b2", kM2, Vec3::Zero(), I));
  system->AddJoint("s1", 0, Transform(), b1, Transform(), JointForm::kParameterized,
                   std::make_shared<SliderModel>(), {Coord("x1", kRatio * 0.1, kRatio * 0.2)});
  system->AddJoint("s2", 0, Transform::Translation(Vec3(0, 1, 0)), b2, Transform(),
                   JointForm::kParameterized, std::make_shared<SliderModel>(),
                   {Coord("x2", 0.1, 0.2)});
  for (int i = 0; i < levers; ++i) {
    system->AddConstraint(std::make_shared<LeverConstraint>(0, 1, kRatio));
  }
  system->Finalize();
  return system;
}

TEST(AddConstraintTest, LeverCouplesTwoSlidersAsTheClosedForm) {
  const auto system = MakeLever();
  ASSERT_EQ(system->constraints().size(), 3u);  // two joints, then the lever
  // Closed form. With x1 = r x2 the kinetic energy is (m1 r^2 + m2) x2'^2 / 2 and gravity's
  // generalized force on x2 is -g (m2 + r m1):
  //   x2'' = a = -g (m2 + r m1) / (m1 r^2 + m2) = -g 6.5 / 18.5.
  const double a = -kG * (kM2 + kRatio * kM1) / (kM1 * kRatio * kRatio + kM2);
  // The KKT rows read M vdot + J' lambda = f, so on x1: m1 x1'' + lambda = -m1 g, i.e.
  //   lambda = -m1 (g + r a) (N), the same from x2: m2 x2'' - r lambda = -m2 g.
  const double lambda = -kM1 * (kG + kRatio * a);
  ASSERT_NEAR(lambda, kM2 * (a + kG) / kRatio, 1e-14);  // the two readings agree

  IntegratorSettings settings;
  settings.accuracy = 1e-10;
  auto integrator = MakeIntegrator("rk45", *system, settings);
  State state = MakeDefaultState(*system);
  Data data(*system);
  const KktSolver& kkt = data.kkt;
  const std::shared_ptr<const Constraint> lever = system->constraints().back();
  // Error bounds: x2'' is constant, so errors grow at most linearly: after N steps x2 is within
  // 2 N accuracy max(1, |x2|) (1 s horizon) and the positions are projected onto the lever to
  // min(1e-3 accuracy, 1e-10). The multiplier is one sparse solve of O(1) entries: rounding.
  const double projection_tolerance = std::min(1e-3 * settings.accuracy, 1e-10);
  double worst_x2 = 0.0, worst_phi = 0.0, worst_lambda = 0.0;
  for (double t : {0.0, 0.25, 0.5, 0.75, 1.0}) {
    integrator->StepTo(state, t);
    const double steps = static_cast<double>(integrator->stats().steps);
    const double x2 = 0.1 + 0.2 * t + 0.5 * a * t * t;
    EXPECT_NEAR(state.q[1], x2, 2.0 * std::max(1.0, steps) * settings.accuracy) << t;
    EXPECT_NEAR(state.u[1], 0.2 + a * t, std::max(1.0, steps) * settings.accuracy) << t;
    VecX phi(1);
    lever->CalcPositionError(*system, state, phi);
    EXPECT_LE(std::abs(phi[0]), projection_tolerance) << t;
    EXPECT_NEAR(state.q[0] - kRatio * state.q[1], phi[0], 1e-15);
    EXPECT_NEAR(state.u[0] - kRatio * state.u[1], 0.0, 1e-13) << t;
    const Accelerations acc = CalcAccelerations(*system, state, nullptr, data);
    const double lambda_t = acc.lambda[kkt.EquationRow(2)];
    EXPECT_NEAR(lambda_t, lambda, 1e-12 * kM1 * kG) << t;
    EXPECT_NEAR(acc.vdot[kkt.SpeedColumn(1)], a, 1e-12 * kG) << t;
    worst_x2 = std::max(worst_x2, std::abs(state.q[1] - x2));
    worst_phi = std::max(worst_phi, std::abs(phi[0]));
    worst_lambda = std::max(worst_lambda, std::abs(lambda_t - lambda));
  }
  std::cout << "x2 error " << worst_x2 << " m, lever residual " << worst_phi
            << " m, multiplier error " << worst_lambda << " N (lambda = " << lambda << " N)\n";
}

// A 12-link chain of parameterized pins (alternating about z and x) with two levers coupling
// coordinates of distant joints, q2 = 0.5 q7 and q4 = -q9.
std::unique_ptr<System> MakeCoupledChain() {
  auto system = std::make_unique<System>(Vec3(0, -9.81, 0));
  const Mat3 y_to_z = Eigen::AngleAxisd(M_PI / 2, Vec3::UnitY()).toRotationMatrix();
  int parent = 0;
  for (int i = 0; i < 12; ++i) {
    const int b = system->AddBody(MakeBody("link" + std::to_string(i), 0.5, Vec3(0, -0.05, 0),
                                           Vec3(4e-4, 1e-4, 4e-4).asDiagonal()));
    const Mat3 R = (i % 2 == 0) ? Mat3::Identity() : y_to_z;
    system->AddJoint("pin" + std::to_string(i), parent,
                     Transform(R, parent == 0 ? Vec3::Zero() : Vec3(0, -0.1, 0)), b,
                     Transform::Rotation(R), JointForm::kParameterized,
                     std::make_shared<testing::RevoluteModel>(Vec3::UnitZ()),
                     {Coord("q" + std::to_string(i), 0.1 * i, 0.2)});
    parent = b;
  }
  system->AddConstraint(std::make_shared<LeverConstraint>(2, 7, 0.5));
  system->AddConstraint(std::make_shared<LeverConstraint>(4, 9, -1.0));
  system->Finalize();
  return system;
}

TEST(AddConstraintTest, CouplersOnTheTreePathEqualTheDenseSolve) {
  const auto system = MakeCoupledChain();
  State state = MakeDefaultState(*system);  // projected onto the levers
  VecX phi(1);
  system->constraints().back()->CalcPositionError(*system, state, phi);
  EXPECT_LT(std::abs(phi[0]), 1e-12);
  for (int c = 0; c < system->num_coordinates(); ++c) state.u[c] = std::cos(1.0 + c);
  PlaceBodies(*system, state);
  Data tree_data(*system), dense(*system, KktSolver::Method::kDense);
  const KktSolver& tree = tree_data.kkt;
  EXPECT_EQ(tree.num_extra_equations(), 2);  // the levers; the joints stay in the tree
  const Accelerations a = CalcAccelerations(*system, state, nullptr, tree_data);
  const Accelerations b = CalcAccelerations(*system, state, nullptr, dense);
  EXPECT_LT((a.vdot - b.vdot).lpNorm<Eigen::Infinity>(), 1e-10 * (1 + b.vdot.norm()));
  EXPECT_LT((a.lambda - b.lambda).lpNorm<Eigen::Infinity>(), 1e-10 * (1 + b.lambda.norm()));
  // The coupled accelerations obey the levers: q2'' = 0.5 q7'', q4'' = -q9''.
  EXPECT_NEAR(a.vdot[tree.SpeedColumn(2)], 0.5 * a.vdot[tree.SpeedColumn(7)],
              1e-10 * (1 + a.vdot.norm()));
  EXPECT_NEAR(a.vdot[tree.SpeedColumn(4)], -a.vdot[tree.SpeedColumn(9)],
              1e-10 * (1 + a.vdot.norm()));
}

TEST(AddConstraintTest, RedundantCouplerIsSolvable) {
  // The same lever twice: the Schur complement is singular, the multipliers split the load
  // (minimum norm), and the motion is that of one lever.
  const auto twice = MakeLever(2);
  const auto once = MakeLever();
  State s2 = MakeDefaultState(*twice), s1 = MakeDefaultState(*once);
  Data d2(*twice), d1(*once);
  const KktSolver &k2 = d2.kkt, &k1 = d1.kkt;
  const Accelerations a2 = CalcAccelerations(*twice, s2, nullptr, d2);
  const Accelerations a1 = CalcAccelerations(*once, s1, nullptr, d1);
  EXPECT_NEAR(a2.vdot[k2.SpeedColumn(1)], a1.vdot[k1.SpeedColumn(1)], 1e-12 * kG);
  EXPECT_NEAR(a2.lambda[k2.EquationRow(2)], a2.lambda[k2.EquationRow(3)], 1e-9 * kM1 * kG);
  EXPECT_NEAR(a2.lambda[k2.EquationRow(2)] + a2.lambda[k2.EquationRow(3)],
              a1.lambda[k1.EquationRow(2)], 1e-9 * kM1 * kG);
}

TEST(AddConstraintTest, UnitLoadResponsesThroughCouplersEqualFullSolves) {
  // The twist responses NSC contact reads (KktSolver::SolveUnitLoadResponses: tree paths plus
  // the Schur correction) against six full solves per loaded body, to rounding: through the
  // levers of the coupled chain, and through the redundant lever pair, whose singular Schur
  // complement goes by its pseudo-inverse (and whose responses are the single lever's).
  const auto chain = MakeCoupledChain();
  State state = MakeDefaultState(*chain);
  PlaceBodies(*chain, state);
  KktSolver kkt(*chain);
  kkt.Factorize(state);
  ASSERT_EQ(kkt.num_extra_equations(), 2);
  std::vector<int> bodies;
  for (int b = 1; b < chain->num_bodies(); ++b) bodies.push_back(b);
  for (int source : bodies) {
    EXPECT_LT(testing::UnitLoadResponseError(kkt, source, bodies), 1e-12) << source;
  }
  const auto twice = MakeLever(2);
  const auto once = MakeLever();
  KktSolver k2(*twice), k1(*once);
  k2.Factorize(MakeDefaultState(*twice));
  k1.Factorize(MakeDefaultState(*once));
  const std::vector<int> both = {1, 2};
  MatX r2(12, 6), r1(12, 6);
  for (int source : both) {
    EXPECT_LT(testing::UnitLoadResponseError(k2, source, both), 1e-12) << source;
    ASSERT_TRUE(k2.SolveUnitLoadResponses(source, both, r2));
    ASSERT_TRUE(k1.SolveUnitLoadResponses(source, both, r1));
    EXPECT_LT((r2 - r1).lpNorm<Eigen::Infinity>(), 1e-12 * r1.lpNorm<Eigen::Infinity>()) << source;
  }
}

TEST(AddConstraintTest, OnlyBeforeFinalize) {
  const auto system = MakeLever();
  EXPECT_THROW(system->AddConstraint(std::make_shared<LeverConstraint>(0, 1, 2.0)), Error);
}

}  // namespace
}  // namespace sinew::engine

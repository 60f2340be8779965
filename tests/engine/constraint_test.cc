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
#include <vector>

#include "engine/test_models.h"

namespace sinew::engine {
namespace {

using testing::Coord;
using testing::MakeBody;
using testing::SliderModel;

// phi = q[a] - ratio q[b] = 0 on two integrated slider coordinates (qdot = u):
// J = [1, -ratio] on their speeds, c = 0, b = -Jdot u = 0.
class LeverConstraint final : public Constraint {
 public:
  LeverConstraint(int a, int b, double ratio) : a_(a), b_(b), ratio_(ratio) {}
  int NumEquations() const override { return 1; }
  std::vector<int> Bodies() const override { return {}; }
  std::vector<int> Coordinates() const override { return {a_, b_}; }
  void CalcPositionError(const System&, const State& state, Eigen::Ref<VecX> phi) const override {
    phi[0] = state.q[a_] - ratio_ * state.q[b_];
  }
  void CalcJacobian(const System&, const State&, Eigen::Ref<MatX> J) const override {
    J(0, 0) = 1.0;
    J(0, 1) = -ratio_;
  }
  void CalcAccelerationRhs(const System&, const State&, Eigen::Ref<VecX> b) const override {
    b[0] = 0.0;
  }

 private:
  int a_, b_;
  double ratio_;
};

constexpr double kG = 9.80665;
constexpr double kM1 = 2.0, kM2 = 0.5, kRatio = 3.0;

// Two bodies on sliders along ground x (1 m apart in y), gravity along -x, coupled by
// x1 = 3 x2 through AddConstraint. Start: x2 = 0.1 m, u2 = 0.2 m/s (x1, u1 consistent).
std::unique_ptr<System> MakeLever() {
  auto system = std::make_unique<System>(Vec3(-kG, 0, 0));
  const Mat3 I = 0.01 * Mat3::Identity();
  const int b1 = system->AddBody(MakeBody("b1", kM1, Vec3::Zero(), I));
  const int b2 = system->AddBody(MakeBody("b2", kM2, Vec3::Zero(), I));
  system->AddJoint("s1", 0, Transform(), b1, Transform(), JointForm::kParameterized,
                   std::make_shared<SliderModel>(), {Coord("x1", kRatio * 0.1, kRatio * 0.2)});
  system->AddJoint("s2", 0, Transform::Translation(Vec3(0, 1, 0)), b2, Transform(),
                   JointForm::kParameterized, std::make_shared<SliderModel>(),
                   {Coord("x2", 0.1, 0.2)});
  system->AddConstraint(std::make_shared<LeverConstraint>(0, 1, kRatio));
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
  KktSolver kkt(*system);
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
    const Accelerations acc = CalcAccelerations(*system, state, nullptr, kkt);
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

TEST(AddConstraintTest, OnlyBeforeFinalize) {
  const auto system = MakeLever();
  EXPECT_THROW(system->AddConstraint(std::make_shared<LeverConstraint>(0, 1, 2.0)), Error);
}

}  // namespace
}  // namespace sinew::engine

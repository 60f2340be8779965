// The "cvode" and "cvode-gmres" integrators (SUNDIALS CVODE, BDF) on a constrained chain against
// rk45 at tight accuracy and against energy conservation, and its errors. Its stiff closed-form
// case and the restart after a changed state are in force_interface_test.cc (they use its
// first-order lag).
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/energy.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/kkt.h>
#include <sinew/engine/projection.h>
#include <sinew/engine/state_vector.h>
#include <sinew/engine/system.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "engine/chain_model.h"
#include "engine/test_models.h"

namespace sinew::engine {
namespace {

class CvodeTest : public ::testing::TestWithParam<const char*> {};

TEST_P(CvodeTest, ConstrainedChainFollowsRk45AndConservesEnergy) {
  // Four direct pins: each a set of position constraints, projected after every step.
  const System system = testing::MakeChain(4);
  const State start = MakeDefaultState(system);
  const double e0 = CalcMechanicalEnergy(system, start);
  State reference = start, state = start;
  auto rk45 = MakeIntegrator("rk45", system, {.accuracy = 1e-12});
  const double accuracy = 1e-9;
  auto cvode = MakeIntegrator(GetParam(), system, {.accuracy = accuracy});
  KktSolver kkt(system);
  double q_diff = 0.0, drift = 0.0, phi = 0.0, jv = 0.0;
  for (int i = 1; i <= 20; ++i) {
    const double t = 0.05 * i;
    rk45->StepTo(reference, t);
    cvode->StepTo(state, t);
    q_diff = std::max(q_diff, (state.q - reference.q).lpNorm<Eigen::Infinity>());
    drift = std::max(drift, std::abs(CalcMechanicalEnergy(system, state) - e0));
    phi = std::max(phi, CalcPositionErrors(system, state).lpNorm<Eigen::Infinity>());
    jv = std::max(jv, CalcVelocityErrors(system, state, kkt).lpNorm<Eigen::Infinity>());
  }
  // The global error of a scheme holding its local error to `accuracy` (RMS, unit floor) over
  // its steps; the chain's motion (swings of 0.1 rad at a few rad/s) does not amplify it much
  // within 1 s. The reference is a thousand times more accurate.
  // CVODE's RMS norm bounds a component's local error by sqrt(size) x accuracy.
  const double local = std::sqrt(static_cast<double>(StateVector(system, kkt).size())) * accuracy;
  const double steps = static_cast<double>(cvode->stats().steps);
  EXPECT_LT(q_diff, steps * local);
  // Energy (|e0| ~ 1 J) changes only by the integration error: BDF's numerical damping is of
  // the order of its local error per step.
  EXPECT_LT(drift / std::abs(e0), steps * local);
  // The projection after each step: positions to the constraint tolerance
  // min(1e-3 accuracy, 1e-10), velocities to round-off.
  EXPECT_LT(phi, 1e-12);
  EXPECT_LT(jv, 1e-12);
  std::printf(
      "chain of 4 over 1 s: %s %ld steps, %ld evaluations, |q - q_rk45| %.2g, "
      "relative energy drift %.2g, |phi| %.2g, |Jv| %.2g\n",
      GetParam(), cvode->stats().steps, cvode->stats().evaluations, q_diff, drift / std::abs(e0),
      phi, jv);
}

TEST_P(CvodeTest, DenseOutputMatchesStepsOnTheChain) {
  // Reporting at times inside CVODE's steps (Interpolate) gives the states stepping to those
  // times gives, to the accuracy.
  const System system = testing::MakeChain(3);
  State stepped = MakeDefaultState(system), advanced = stepped;
  const double accuracy = 1e-9;
  auto direct = MakeIntegrator(GetParam(), system, {.accuracy = accuracy});
  auto dense = MakeIntegrator(GetParam(), system, {.accuracy = accuracy});
  ASSERT_TRUE(dense->HasDenseOutput());
  double worst = 0.0;
  State out = advanced;
  for (int i = 1; i <= 10; ++i) {
    const double t = 0.05 * i;
    while (advanced.t < t) dense->Advance(advanced, 1.0);
    dense->Interpolate(t, out);
    direct->StepTo(stepped, t);
    worst = std::max(worst, (out.q - stepped.q).lpNorm<Eigen::Infinity>());
    EXPECT_LT(CalcPositionErrors(system, out).lpNorm<Eigen::Infinity>(), 1e-12);
  }
  const KktSolver kkt(system);
  const double local = std::sqrt(static_cast<double>(StateVector(system, kkt).size())) * accuracy;
  const double steps = static_cast<double>(dense->stats().steps + direct->stats().steps);
  EXPECT_LT(worst, steps * local);
  EXPECT_THROW(dense->Interpolate(advanced.t + 1.0, out), Error);
}

// A state variable whose derivative turns NaN at t = 0.5 s: CVODE cannot step past it.
class Poison final : public ForceElement {
 public:
  std::string name() const override { return "poison"; }
  std::vector<std::string> StateVariableNames() const override { return {"x"}; }
  void CalcStateVariableDerivatives(const ForceContext& context,
                                    Eigen::Ref<VecX> zdot) const override {
    zdot[0] = context.state.t < 0.5 ? 1.0 : std::numeric_limits<double>::quiet_NaN();
  }
  void AddLoads(const ForceContext&, Loads&) const override {}
};

TEST_P(CvodeTest, FailureNamesTheTimeAndCvodesFlag) {
  System system(Vec3::Zero());
  const int b = system.AddBody(testing::MakeBody("block", 1.0, Vec3::Zero(), Mat3::Identity()));
  system.AddJoint("slider", 0, Transform::Identity(), b, Transform::Identity(),
                  JointForm::kParameterized, std::make_shared<testing::SliderModel>(),
                  {testing::Coord("x")});
  system.AddForceElement(std::make_shared<Poison>());
  system.Finalize();
  State state = MakeDefaultState(system);
  auto cvode = MakeIntegrator(GetParam(), system, {.accuracy = 1e-6});
  try {
    cvode->StepTo(state, 1.0);
    FAIL() << "stepped through NaN derivatives";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("integrator '" + std::string(GetParam()) + "'"), std::string::npos)
        << message;
    EXPECT_NE(message.find("CV_"), std::string::npos) << message;  // CVODE's flag name
    EXPECT_NE(message.find("t = 0."), std::string::npos) << message;
    std::printf("%s\n", message.c_str());
  }
  EXPECT_LT(state.t, 0.5 + 1e-9);
}

INSTANTIATE_TEST_SUITE_P(LinearSolvers, CvodeTest, ::testing::Values("cvode", "cvode-gmres", "cvode-gmres-bd"));

TEST(CvodeNamesTest, AreListedAmongTheIntegrators) {
  const System system = testing::MakeChain(1);
  try {
    MakeIntegrator("bdf", system, {});
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("cvode, cvode-gmres"), std::string::npos);
  }
}

}  // namespace
}  // namespace sinew::engine

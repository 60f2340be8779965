// Forces whose loads or state derivatives are not finite: named in the error, and taken by rk45
// as a failed trial step when only a trial stage leaves the force's domain (found on arm26,
// whose TRIlong fiber length went negative in a trial stage across a jump of its path length).
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/dynamics.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/system.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <utility>

#include "engine/test_models.h"

namespace sinew::engine {
namespace {

// A decaying state x' = -x / tau that pushes coordinate 0 with k sqrt(x): defined for x >= 0
// only (as a fiber length is), so an explicit stage that overshoots zero makes its loads NaN.
class SqrtDecay final : public ForceElement {
 public:
  SqrtDecay(double tau, double k, double x0) : tau_(tau), k_(k), x0_(x0) {}
  std::string name() const override { return "decay"; }
  std::vector<std::string> StateVariableNames() const override { return {"x"}; }
  void SetDefaultStateVariables(Eigen::Ref<VecX> z) const override { z[0] = x0_; }
  void CalcStateVariableDerivatives(const ForceContext& context,
                                    Eigen::Ref<VecX> zdot) const override {
    zdot[0] = -context.z(0) / tau_;
  }
  void AddLoads(const ForceContext& context, Loads& loads) const override {
    loads.AddGeneralizedForce(0, k_ * std::sqrt(context.z(0)));
  }

 private:
  double tau_, k_, x0_;
};

// Loads that are NaN from t = 0.5 s on.
class Poisoned final : public ForceElement {
 public:
  std::string name() const override { return "poisoned"; }
  void AddLoads(const ForceContext& context, Loads& loads) const override {
    loads.AddGeneralizedForce(
        0, context.state.t < 0.5 ? 1.0 : std::numeric_limits<double>::quiet_NaN());
  }
};

// A 1 kg slider without gravity at q = 0, pushed by `force`.
System MakeSlider(std::shared_ptr<ForceElement> force) {
  System system(Vec3::Zero());
  const int b =
      system.AddBody(testing::MakeBody("block", 1.0, Vec3::Zero(), 0.1 * Mat3::Identity()));
  system.AddJoint("slider", 0, Transform::Identity(), b, Transform::Identity(),
                  JointForm::kParameterized, std::make_shared<testing::SliderModel>(),
                  {testing::Coord("x")});
  system.AddForceElement(std::move(force));
  system.Finalize();
  return system;
}

TEST(NonFiniteForceTest, AccelerationsNameTheForce) {
  const System system = MakeSlider(std::make_shared<Poisoned>());
  State state = MakeDefaultState(system);
  state.t = 0.7;
  Data data(system);
  try {
    CalcAccelerations(system, state, nullptr, data);
    FAIL() << "accelerations from NaN loads";
  } catch (const NonFiniteForceError& e) {
    EXPECT_EQ(e.component(), "poisoned");
    EXPECT_NE(std::string(e.what()).find("not finite at t = 0.7"), std::string::npos) << e.what();
  }
}

// With tau = 1e-4 s, rk45's first trial step (1 ms) drives x below zero in its stages; it must
// retry shorter and then follow the closed forms x = x0 exp(-t / tau) and
// q = k sqrt(x0) (2 tau)^2 (exp(-t / (2 tau)) - 1 + t / (2 tau)).
TEST(NonFiniteForceTest, Rk45RetriesATrialStepThatLeavesAForcesDomain) {
  const double tau = 1e-4, k = 2.0, x0 = 0.25, t = 2e-3;
  const System system = MakeSlider(std::make_shared<SqrtDecay>(tau, k, x0));
  State state = MakeDefaultState(system);
  auto integrator = MakeIntegrator("rk45", system, {.accuracy = 1e-9});
  integrator->StepTo(state, t);
  EXPECT_GT(integrator->stats().rejected, 0);
  const double x = x0 * std::exp(-t / tau), s = 2 * tau;
  const double q = k * std::sqrt(x0) * s * s * (std::exp(-t / s) - 1 + t / s);
  // Local errors below accuracy (unit floor) per step: the decaying x within steps x accuracy,
  // q integrates it twice over 2 ms.
  const double bound = static_cast<double>(integrator->stats().steps) * 1e-9;
  EXPECT_LT(std::abs(state.z[0] - x), bound);
  EXPECT_LT(std::abs(state.q[0] - q), bound);
}

// Loads NaN everywhere beyond t = 0.5 s: no step gets past, and the error says why.
TEST(NonFiniteForceTest, Rk45FailureNamesTheForce) {
  const System system = MakeSlider(std::make_shared<Poisoned>());
  State state = MakeDefaultState(system);
  auto integrator = MakeIntegrator("rk45", system, {.accuracy = 1e-6});
  try {
    integrator->StepTo(state, 1.0);
    FAIL() << "stepped through NaN loads";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("step size fell below"), std::string::npos) << message;
    EXPECT_NE(message.find("poisoned"), std::string::npos) << message;
  }
  EXPECT_LT(state.t, 0.5 + 1e-9);
}

}  // namespace
}  // namespace sinew::engine

// The linearized implicit Euler scheme on a stiff spring: stable where the semi-implicit
// (symplectic) Euler blows up, and first-order accurate on a smooth problem.
#include <gtest/gtest.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/loads.h>
#include <sinew/engine/system.h>

#include <cmath>
#include <memory>

#include "engine/test_models.h"

namespace sinew::engine {
namespace {

// Generalized spring-damper force -k q - c u on coordinate 0 (test-only force element).
class SpringDamper final : public ForceElement {
 public:
  SpringDamper(double k, double c) : k_(k), c_(c) {}
  void AddLoads(const ForceContext& context, Loads& loads) const override {
    const State& state = context.state;
    loads.AddGeneralizedForce(0, -k_ * state.q[0] - c_ * state.u[0]);
  }

 private:
  double k_, c_;
};

System MakeSpringSlider(double k, double c) {
  System system(Vec3::Zero());
  const int b =
      system.AddBody(testing::MakeBody("block", 1.0, Vec3::Zero(), 0.1 * Mat3::Identity()));
  system.AddJoint("slider", 0, Transform::Identity(), b, Transform::Identity(),
                  JointForm::kParameterized, std::make_shared<testing::SliderModel>(),
                  {testing::Coord("x", 0.01)});
  system.AddForceElement(std::make_shared<SpringDamper>(k, c));
  system.Finalize();
  return system;
}

TEST(ImplicitEulerTest, StiffSpringStaysBoundedWhereSymplecticEulerDiverges) {
  // omega = 1e4 rad/s, h = 1e-3 s: h omega = 10, far beyond symplectic Euler's limit of 2.
  const System system = MakeSpringSlider(1e8, 0.0);
  IntegratorSettings settings;
  settings.step = 1e-3;
  State implicit_state = MakeDefaultState(system);
  MakeIntegrator("implicit-euler", system, settings)->StepTo(implicit_state, 0.05);
  EXPECT_TRUE(std::isfinite(implicit_state.q[0]));
  EXPECT_LE(std::abs(implicit_state.q[0]), 0.01);  // implicit Euler only damps
  State explicit_state = MakeDefaultState(system);
  MakeIntegrator("euler", system, settings)->StepTo(explicit_state, 0.05);
  EXPECT_FALSE(std::abs(explicit_state.q[0]) < 1.0);  // grew by > 100x (or overflowed)
}

TEST(ImplicitEulerTest, FirstOrderOnASoftDampedSpring) {
  // m = 1, k = 4, c = 0.4: x(t) = A exp(-0.2 t) cos(w t) + B ..., w = sqrt(4 - 0.04).
  const System system = MakeSpringSlider(4.0, 0.4);
  const double w = std::sqrt(4.0 - 0.04);
  const double exact = 0.01 * std::exp(-0.2) * (std::cos(w) + 0.2 / w * std::sin(w));
  double errors[2];
  for (int i = 0; i < 2; ++i) {
    IntegratorSettings settings;
    settings.step = i == 0 ? 2e-3 : 1e-3;
    State state = MakeDefaultState(system);
    MakeIntegrator("implicit-euler", system, settings)->StepTo(state, 1.0);
    errors[i] = std::abs(state.q[0] - exact);
  }
  EXPECT_LT(errors[1], 1e-4);
  EXPECT_NEAR(errors[0] / errors[1], 2.0, 0.3);
}

}  // namespace
}  // namespace sinew::engine

// Position projection after a fixed step: a step too large to project back onto the
// constraints is a sinew::Error that says what failed, when, and what to try; and the 1000-link
// chain of benchmarks/engine_chain.cc steps with Euler at 1 ms past t = 0.067 s, where the
// projection used to stall (its modified Newton kept a stale matrix while the error fell by only
// ~10x per iteration and ran out of iterations at 1.3e-10 against a tolerance of 1e-10).
//
// The fixed-step schemes move the bodies along the joint tree (ApplyTreeDisplacement), so the
// tree's joints hold after any step and only loop joints and extra constraints can fail to
// project: the absurd step is taken on a rod closed into a pin by a loop joint.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/projection.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "engine/chain_model.h"
#include "engine/test_models.h"

namespace sinew::engine {
namespace {

System MakeRodClosedIntoAPin() {
  System system(Vec3(0, -9.81, 0));
  // The rod's origin is its mass centre, 0.5 m from the pin (which is at the ground's origin).
  const int rod =
      system.AddBody(testing::MakeBody("rod", 2.0, Vec3::Zero(), 0.02 * Mat3::Identity()));
  const double angle = 0.8;
  std::vector<CoordinateDesc> free_coordinates;
  for (const char* name : {"rx", "ry", "rz", "tx", "ty", "tz"}) {
    free_coordinates.push_back(testing::Coord(name));
  }
  free_coordinates[2].default_value = angle;
  free_coordinates[3].default_value = 0.5 * std::sin(angle);
  free_coordinates[4].default_value = -0.5 * std::cos(angle);
  system.AddJoint("free", 0, Transform::Identity(), rod, Transform::Identity(),
                  JointForm::kParameterized, std::make_shared<testing::FreeModel>(),
                  free_coordinates);
  system.AddJoint("pin", 0, Transform::Identity(), rod, Transform::Translation(Vec3(0, 0.5, 0)),
                  JointForm::kPin, nullptr, {testing::Coord("q", angle)});
  system.Finalize();
  return system;
}

TEST(ProjectionFailureTest, AbsurdFixedStepIsAnErrorSayingWhenAndWhatToTry) {
  // A rod on a free joint, held 0.5 m from its mass centre by a pin to ground that closes a loop, at rest at
  // 0.8 rad: a 10 s Euler step drops the free rod by about g h^2 ~ 1 km. (`sinew simulate`
  // checks the same message for implicit-euler, which shares the projection step, on a model
  // that integrator cannot step either: tests/apps/projection_failure_test.cc.)
  const System system = MakeRodClosedIntoAPin();
  State state = MakeDefaultState(system);
  IntegratorSettings settings;
  settings.step = 10.0;
  const auto integrator = MakeIntegrator("euler", system, settings);
  std::string message;
  try {
    integrator->StepTo(state, 10.0);
  } catch (const Error& e) {
    message = e.what();
  }
  EXPECT_NE(
      message.find("integrator 'euler': position projection failed in the step from t = 0 s to "
                   "t = 10 s: the largest constraint error is still"),
      std::string::npos)
      << message;
  EXPECT_NE(message.find("after 10 Newton iterations (tolerance 1e-10)"), std::string::npos)
      << message;
  EXPECT_NE(message.find("A fixed step of 10 s is likely too large"), std::string::npos) << message;
  EXPECT_NE(message.find("try a smaller step, or the error-controlled integrator rk45"),
            std::string::npos)
      << message;
  EXPECT_EQ(integrator->stats().projection_failures, 1);
  EXPECT_EQ(state.t, 0.0) << "a failed step leaves the state where it was";
}

TEST(ProjectionFailureTest, ThousandLinkChainEulerStepsStayOnTheJoints) {
  const System system = testing::MakeChain(1000);
  State state = MakeDefaultState(system);
  IntegratorSettings settings;
  settings.step = 1e-3;
  const auto integrator = MakeIntegrator("euler", system, settings);
  // One step per call, as the benchmark took them (the failure was in the 67th step).
  for (int i = 0; i < 70; ++i) {
    ASSERT_NO_THROW(integrator->StepTo(state, state.t + 1e-3)) << "step " << i + 1;
    // Every accepted step ends on the joints (the integrator's tolerance).
    ASSERT_LE(CalcPositionErrors(system, state).lpNorm<Eigen::Infinity>(), 1e-10);
  }
  EXPECT_NEAR(state.t, 0.07, 1e-12);
  EXPECT_EQ(integrator->stats().projection_failures, 0);
}

}  // namespace
}  // namespace sinew::engine

// Forces on a FunctionBasedPath through the OpenSim parser and the engine: a PathSpring on a
// polynomial path of a double pendulum conserves energy (its generalized force is the
// gradient of its potential), and on the slider a FunctionBasedPath whose length function is
// the slider path's exact length, L = x + 0.3, moves the block exactly as that GeometryPath
// does (spring: the closed form; Thelen muscle: the same run).
#include <gtest/gtest.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/energy.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/pose.h>
#include <sinew/functions/constant.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "slider_model.h"

namespace sinew::muscles {
namespace {

const std::string kModel = std::string(SINEW_TEST_DATA_DIR) + "/sinew/function_based_paths.osim";

// The slider's path as a FunctionBasedPath: the ground point is 0.3 m behind the block's
// origin at x = 0, so the straight path's length is exactly x + 0.3 (for x > -0.3 m).
constexpr char kFunctionPath[] = R"(<FunctionBasedPath name="path">
<coordinate_paths>/jointset/slide/x</coordinate_paths>
<length_function><LinearFunction><coefficients>1 0.3</coefficients></LinearFunction></length_function>
</FunctionBasedPath>)";

TEST(FunctionBasedPathDynamicsTest, SpringOnAPolynomialPathConservesEnergy) {
  auto parsed = ParseFile(kModel);
  auto integrator = engine::MakeIntegrator("rk45", *parsed->system, {.accuracy = 1e-11});
  engine::State state = engine::MakeDefaultState(*parsed->system);
  // The spring's potential at the start: L(0.3, -0.2) = 0.28315 m, stretch 0.23315 m.
  const double energy0 = engine::CalcMechanicalEnergy(*parsed->system, state);
  const double spring0 = 0.5 * 80 * 0.23315 * 0.23315;
  const double q1_0 = engine::GetCoordinateValue(*parsed->system, state, "q1");
  for (double t : {0.25, 0.5, 1.0}) {
    integrator->StepTo(state, t);
    EXPECT_NEAR(engine::CalcMechanicalEnergy(*parsed->system, state), energy0, 1e-8) << t;
  }
  // The pendulum moved, so energy was exchanged (the spring's share is ~2 J).
  EXPECT_GT(std::abs(engine::GetCoordinateValue(*parsed->system, state, "q1") - q1_0), 0.05);
  EXPECT_GT(spring0, 2.0);
}

TEST(FunctionBasedPathDynamicsTest, SpringOnTheSliderFollowsTheClosedForm) {
  // As PathSpringTest, on the FunctionBasedPath.
  ExpectStretchedSpringOscillatesAsTheClosedForm(kFunctionPath);
}

// The block's position and speed and the muscle's states after `duration` s of a Thelen
// muscle (excitation 0.6) on `path`, the slider free.
std::vector<double> RunThelen(const std::string& path, double duration) {
  const std::string muscle =
      std::string(R"(<Thelen2003Muscle name="musc">)") + path +
      R"(<max_isometric_force>500</max_isometric_force><optimal_fiber_length>0.12</optimal_fiber_length>
<tendon_slack_length>0.27</tendon_slack_length><pennation_angle_at_optimal>0.2</pennation_angle_at_optimal>
<default_activation>0.2</default_activation></Thelen2003Muscle>)";
  auto parsed = Parse(SliderModel(muscle, false), /*equilibrate=*/true);
  parsed->parser.SetExcitationFunction("musc", std::make_shared<functions::Constant>(0.6));
  auto integrator = engine::MakeIntegrator("rk45", *parsed->system, {.accuracy = 1e-10});
  integrator->SetController(parsed->parser.GetController());
  engine::State state = engine::MakeDefaultState(*parsed->system);
  integrator->StepTo(state, duration);
  std::vector<double> out{engine::GetCoordinateValue(*parsed->system, state, "x"),
                          engine::GetCoordinateSpeed(*parsed->system, state, "x")};
  out.insert(out.end(), state.z.begin(), state.z.end());
  return out;
}

TEST(FunctionBasedPathDynamicsTest, MuscleOnTheExactFunctionPathMovesAsOnTheGeometryPath) {
  const std::vector<double> geometry = RunThelen(kPath, 0.1);
  const std::vector<double> function = RunThelen(kFunctionPath, 0.1);
  ASSERT_EQ(function.size(), geometry.size());
  ASSERT_EQ(geometry.size(), 4u);  // x, u, activation, fiber length
  // The muscle pulled the block (it moved), and the two runs are one run to within the
  // integrator's error control (1e-10) on the same equations.
  EXPECT_GT(std::abs(geometry[0] - 0.1), 1e-3);
  for (size_t k = 0; k < geometry.size(); ++k) {
    EXPECT_NEAR(function[k], geometry[k], 1e-8) << k;
  }
}

}  // namespace
}  // namespace sinew::muscles

// RigidTendonMuscle through the parser and the engine: a block pulled along a slider by one
// such muscle follows the one-degree-of-freedom equation its law gives, integrated here with
// classical Runge-Kutta (curves given in the file as simple functions, so the law is written
// out independently); the default curves are OpenSim's; the power of its loads is -T dL/dt.
#include <gtest/gtest.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/energy.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/pose.h>
#include <sinew/functions/constant.h>
#include <sinew/muscles/path_actuator.h>
#include <sinew/muscles/simm_muscle_spec.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "slider_model.h"

namespace sinew::muscles {
namespace {

constexpr double kFiso = 100.0, kOptimal = 0.1, kSlack = 0.2, kPennation = 0.3, kVmax = 10.0;
constexpr double kExcitation = 0.5, kMass = 2.0;

std::string RigidTendon(const std::string& curves) {
  return std::string(R"(<RigidTendonMuscle name="musc">)") + kPath +
         R"(<max_isometric_force>100</max_isometric_force><optimal_fiber_length>0.1</optimal_fiber_length>
<tendon_slack_length>0.2</tendon_slack_length><pennation_angle_at_optimal>0.3</pennation_angle_at_optimal>
<max_contraction_velocity>10</max_contraction_velocity>)" +
         curves + "</RigidTendonMuscle>";
}

// fal = 0.8, fpe = 2 (lceN - 1) (clamped into [0, 10] as OpenSim clamps it), fv = 1 + vN / 2.
const char* kSimpleCurves =
    R"(<Constant name="active_force_length_curve"><value>0.8</value></Constant>
<LinearFunction name="passive_force_length_curve"><coefficients>2 -2</coefficients></LinearFunction>
<LinearFunction name="force_velocity_curve"><coefficients>0.5 1</coefficients></LinearFunction>)";

// The tension of that muscle on the slider's path (length x + 0.3) at block position x, speed v:
// the tendon keeps its slack length, the fiber is the hypotenuse over the rest of the path and
// the muscle's width, its velocity the path's speed.
double Tension(double x, double v) {
  const double along = std::max(x + 0.3 - kSlack, 0.0);
  const double width = kOptimal * std::sin(kPennation);
  const double fiber = std::hypot(along, width);
  const double lceN = fiber / kOptimal, vN = v / (kOptimal * kVmax);
  const double fpe = std::clamp(2.0 * (lceN - 1.0), 0.0, 10.0);
  return kFiso * (kExcitation * 0.8 * (1.0 + 0.5 * vN) + fpe) * along / fiber;
}

// x'' = -T / m by classical Runge-Kutta with step h.
std::array<double, 2> IntegrateBlock(double t_end, double h) {
  std::array<double, 2> y{0.1, 0.0};
  auto f = [](const std::array<double, 2>& s) {
    return std::array<double, 2>{s[1], -Tension(s[0], s[1]) / kMass};
  };
  for (double t = 0.0; t < t_end - 0.5 * h; t += h) {
    const auto k1 = f(y);
    const auto k2 = f({y[0] + 0.5 * h * k1[0], y[1] + 0.5 * h * k1[1]});
    const auto k3 = f({y[0] + 0.5 * h * k2[0], y[1] + 0.5 * h * k2[1]});
    const auto k4 = f({y[0] + h * k3[0], y[1] + h * k3[1]});
    for (int i = 0; i < 2; ++i) y[i] += h / 6.0 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
  }
  return y;
}

TEST(RigidTendonMuscleTest, BlockFollowsTheEquationOfItsLaw) {
  auto parsed = Parse(SliderModel(RigidTendon(kSimpleCurves), false));
  ASSERT_TRUE(parsed->system->state_variable_names().empty());  // no fiber, no activation state
  parsed->parser.SetExcitationFunction("musc", std::make_shared<functions::Constant>(kExcitation));
  auto integrator = engine::MakeIntegrator("rk45", *parsed->system, {.accuracy = 1e-11});
  integrator->SetController(parsed->parser.GetController());
  engine::State state = engine::MakeDefaultState(*parsed->system);
  // The run passes the passive curve's corner (fiber at its optimal length, x = -0.0045 m);
  // RK4 with h = 1e-5 s is accurate to about 1e-10 m across it.
  for (double t : {0.02, 0.05, 0.1}) {
    integrator->StepTo(state, t);
    const auto reference = IntegrateBlock(t, 1e-5);
    EXPECT_NEAR(engine::GetCoordinateValue(*parsed->system, state, "x"), reference[0], 1e-8) << t;
    std::printf("t = %g: x = %.6f m, differs from RK4 by %.3g m\n", t, reference[0],
                engine::GetCoordinateValue(*parsed->system, state, "x") - reference[0]);
    EXPECT_NEAR(engine::GetCoordinateSpeed(*parsed->system, state, "x"), reference[1], 1e-6) << t;
    // The power of the muscle's loads is -tension times the path's lengthening speed.
    const auto& muscle = dynamic_cast<const PathActuator&>(*parsed->system->force_elements()[0]);
    const engine::ForceContext context = parsed->system->MakeForceContext(0, state);
    const double tension = muscle.CalcQuantities(context).tendon_force;
    EXPECT_NEAR(engine::CalcForcePower(*parsed->system, state, 0),
                -tension * muscle.CalcPathKinematics(context).lengthening_speed,
                1e-9 * std::abs(tension));
  }
  EXPECT_LT(engine::GetCoordinateValue(*parsed->system, state, "x"), -0.0045);  // past the corner
}

TEST(RigidTendonMuscleTest, DefaultCurvesAreOpenSims) {
  const model::ModelSpec spec = io::ReadOsimString(SliderModel(RigidTendon(""), true), "m.osim");
  const RigidTendonMuscle muscle = ReadRigidTendonMuscle(spec, spec.forces.at(0));
  const RigidTendonParameters& p = muscle.parameters();
  // Knots of OpenSim's constructor: active (1.045, 0.993333), passive (1.5, 1.17),
  // force-velocity (-0.5, 0.166667), (0, 1), (0.5, 1.75049).
  EXPECT_NEAR(p.active_force_length_curve->Calc(1.045), 0.993333, 1e-13);
  EXPECT_NEAR(p.passive_force_length_curve->Calc(1.5), 1.17, 1e-13);
  EXPECT_NEAR(p.force_velocity_curve->Calc(-0.5), 0.166667, 1e-13);
  EXPECT_NEAR(p.force_velocity_curve->Calc(0.0), 1.0, 1e-13);
  EXPECT_NEAR(p.force_velocity_curve->Calc(0.5), 1.75049, 1e-13);
  // At the slider's default (path 0.4 m, at rest) with excitation 0.5 the tension is
  // (0.5 fal + fpe) Fiso cos at the hypotenuse fiber.
  const double fiber = std::hypot(0.2, 0.1 * std::sin(0.3)), lceN = fiber / 0.1;
  const MuscleQuantities q = muscle.Calc(VecX(), 0.5, {0.4, 0.0});
  EXPECT_NEAR(q.fiber_length, fiber, 1e-15);
  EXPECT_NEAR(q.tendon_length, 0.2, 1e-15);
  EXPECT_NEAR(q.tendon_force,
              100.0 *
                  (0.5 * p.active_force_length_curve->Calc(lceN) +
                   p.passive_force_length_curve->Calc(lceN)) *
                  0.2 / fiber,
              1e-12);
}

}  // namespace
}  // namespace sinew::muscles

// The simulation driver: reports at every report time, from rk45's dense output without
// cutting steps (checked against the closed form of a pendulum-free lagged slider), the same
// reports from fixed-step schemes, and a clean early stop.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/simulation.h>
#include <sinew/engine/system.h>

#include <atomic>
#include <cmath>
#include <memory>
#include <vector>

#include "engine/test_models.h"

namespace sinew::engine {
namespace {

using testing::Coord;
using testing::MakeBody;

// A slider (1 kg, no gravity) pulled back by a spring of stiffness 4 N/m: x = x0 cos(2 t).
System MakeOscillator() {
  System system(Vec3::Zero());
  const int b = system.AddBody(MakeBody("block", 1.0, Vec3::Zero(), Mat3::Identity()));
  system.AddJoint("slider", 0, Transform::Identity(), b, Transform::Identity(),
                  JointForm::kParameterized, std::make_shared<testing::SliderModel>(),
                  {Coord("x", 0.3)});
  class Spring final : public ForceElement {
   public:
    void AddLoads(const ForceContext& context, Loads& loads) const override {
      loads.AddGeneralizedForce(0, -4.0 * context.state.q[0]);
    }
  };
  system.AddForceElement(std::make_shared<Spring>());
  system.Finalize();
  return system;
}

TEST(SimulationTest, DenseOutputReportsWithoutCuttingSteps) {
  const System system = MakeOscillator();
  State state = MakeDefaultState(system);
  IntegratorSettings settings;
  settings.accuracy = 1e-8;
  auto integrator = MakeIntegrator("rk45", system, settings);
  SimulationOptions options;
  options.duration = 2.0;
  options.report_interval = 1e-3;
  std::vector<double> times;
  double worst = 0.0;
  const SimulationResult result = Simulate(*integrator, state, options, [&](const State& s) {
    times.push_back(s.t);
    worst = std::max(worst, std::abs(s.q[0] - 0.3 * std::cos(2 * s.t)));
  });
  EXPECT_TRUE(result.completed);
  ASSERT_EQ(times.size(), 2001u);
  EXPECT_EQ(result.reports, 2001);
  for (size_t i = 0; i < times.size(); ++i) EXPECT_NEAR(times[i], 1e-3 * i, 1e-12);
  EXPECT_EQ(state.t, 2.0);
  // Far fewer steps than reports: the steps were not cut at report times.
  EXPECT_LT(integrator->stats().steps, 200);
  // The interpolant is fourth order, as accurate as the steps themselves: every reported
  // value within the global error bound steps x accuracy (x the unit floor), times 10 for the
  // interpolation.
  EXPECT_LT(worst, 10.0 * static_cast<double>(integrator->stats().steps) * settings.accuracy);
}

TEST(SimulationTest, FixedStepSchemesReportAtTheSameTimes) {
  const System system = MakeOscillator();
  State state = MakeDefaultState(system);
  IntegratorSettings settings;
  settings.step = 1e-3;
  auto integrator = MakeIntegrator("euler", system, settings);
  SimulationOptions options;
  options.duration = 0.105;  // the last interval is shorter
  options.report_interval = 0.01;
  std::vector<double> times;
  Simulate(*integrator, state, options, [&](const State& s) { times.push_back(s.t); });
  ASSERT_EQ(times.size(), 12u);
  EXPECT_NEAR(times[10], 0.1, 1e-12);
  EXPECT_EQ(times.back(), 0.105);
}

TEST(SimulationTest, StopFlagEndsTheRunCleanly) {
  const System system = MakeOscillator();
  State state = MakeDefaultState(system);
  auto integrator = MakeIntegrator("rk45", system, IntegratorSettings{});
  std::atomic<bool> stop{false};
  SimulationOptions options;
  options.duration = 10.0;
  options.report_interval = 0.01;
  options.stop = &stop;
  long seen = 0;
  const SimulationResult result = Simulate(*integrator, state, options, [&](const State& s) {
    if (++seen == 50) stop = true;  // as a signal handler would, in the middle of the run
    EXPECT_LE(s.t, 10.0);
  });
  EXPECT_FALSE(result.completed);
  EXPECT_EQ(result.reports, seen);
  EXPECT_LT(state.t, 1.0);
  EXPECT_GE(seen, 50);
}

TEST(SimulationTest, BadOptionsAreErrors) {
  const System system = MakeOscillator();
  State state = MakeDefaultState(system);
  auto integrator = MakeIntegrator("rk45", system, IntegratorSettings{});
  SimulationOptions options;
  options.duration = std::numeric_limits<double>::infinity();
  EXPECT_THROW(Simulate(*integrator, state, options, [](const State&) {}), Error);
  options.duration = 1.0;
  options.report_interval = 0.0;
  EXPECT_THROW(Simulate(*integrator, state, options, [](const State&) {}), Error);
}

}  // namespace
}  // namespace sinew::engine

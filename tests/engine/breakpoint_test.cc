// rk45 and the breakpoints of the models' splines, where a coordinate crossing them makes the
// accelerations jump (a cubic spline's ends, past which OpenSim's SimmSpline extrapolates
// linearly, so f'' and the velocity-product terms jump) or their rate of change (its inner
// knots, where f''' jumps): Rajagopal2016's walker knees and patella couplers, whose SimmSplines
// have knots every 10 degrees from 0 to 2.0944 rad of knee angle. A trial step across one that
// fails its error test is retried to end just short of it, and the next step starts by crossing
// it (System::breakpoints).
#include <gtest/gtest.h>
#include <sinew/engine/energy.h>

#include <cmath>
#include <iostream>
#include <map>
#include <utility>

#include "engine/hung_skeleton.h"

namespace sinew::engine {
namespace {

TEST(BreakpointTest, KnotsOfRajagopalsKneeSplinesAreListed) {
  const testing::HungSkeleton hung =
      testing::MakeHungSkeleton(testing::kRajagopal2016HungFile, true, 1.0);
  const System& system = *hung.system;
  std::map<std::string, std::vector<double>> listed;
  for (const auto& [coordinate, value] : system.breakpoints()) {
    listed[system.coordinates()[coordinate].name].push_back(value);
  }
  // Each knee's rotation and translation splines (knee_angle_*), the patellae's
  // (knee_angle_*_beta), and the couplers' functions of the knee angles: the 13 knots, 0 to
  // 2.0944 rad every 10 degrees (as the file writes them, to 6 digits), once per coordinate.
  for (const char* name :
       {"knee_angle_r", "knee_angle_l", "knee_angle_r_beta", "knee_angle_l_beta"}) {
    ASSERT_EQ(listed[name].size(), 13u) << name;
    for (int k = 0; k < 13; ++k) {
      EXPECT_NEAR(listed[name][k], k * M_PI / 18.0, 5e-6) << name << " knot " << k;
    }
  }
  EXPECT_EQ(listed.size(), 4u);  // the pelvis is locked; no other joint has a spline
}

TEST(BreakpointTest, HungRajagopalCrossesTheKneeSplineEndsAtStepsEnds) {
  // The hung skeleton's second (BM_Rajagopal2016HungOneSecond), its right knee crossing 0 at
  // 10.7 and 12.7 rad/s. Reported every millisecond. A step across a spline's end at such
  // speeds fails its error test by orders of magnitude and is retried to end there, so at least
  // as many breakpoints are crossed at steps' ends as ends are crossed between reports; inner
  // knots are crossed there only when a step across them failed, so at most all those seen. The
  // run keeps the accuracy's error against a tight reference and the mechanical energy (gravity
  // alone acts).
  const testing::HungSkeleton hung =
      testing::MakeHungSkeleton(testing::kRajagopal2016HungFile, true, 1.0);
  const System& system = *hung.system;
  State state = hung.start;
  IntegratorSettings settings;
  settings.accuracy = 1e-7;
  settings.constraint_tolerance = 1e-10;
  const auto integrator = MakeIntegrator("rk45", system, settings);
  const double energy0 = CalcMechanicalEnergy(system, state);
  double worst_energy = 0.0;
  long ends_seen = 0, seen = 0;
  for (int ms = 1; ms <= 1000; ++ms) {
    const State before = state;
    integrator->StepTo(state, 1e-3 * ms);
    for (const auto& [coordinate, value] : system.breakpoints()) {
      if ((before.q[coordinate] - value) * (state.q[coordinate] - value) >= 0.0) continue;
      ++seen;
      if (value == 0.0 || std::abs(value - 2.0944) < 1e-12) ++ends_seen;
    }
    worst_energy = std::max(worst_energy, std::abs(CalcMechanicalEnergy(system, state) - energy0));
  }
  const IntegratorStats& stats = integrator->stats();
  EXPECT_GE(ends_seen, 4);  // the right knee and its patella, twice
  EXPECT_GE(stats.breakpoints_crossed, ends_seen);
  EXPECT_LE(stats.breakpoints_crossed, seen);
  const State reference = testing::RunHung(hung, "rk45", 1e-11, nullptr);
  double error = 0.0;
  for (int c = 0; c < system.num_coordinates(); ++c) {
    error = std::max(error, std::abs(state.q[c] - reference.q[c]));
  }
  // rk45's global error at accuracy 1e-7 over the second is of the order of 10 accuracies.
  EXPECT_LT(error, 1e-6);
  EXPECT_LT(worst_energy, 1e-6 * std::abs(energy0));
  std::cout << "hung Rajagopal2016 at 1e-7: " << seen << " knots crossed (" << ends_seen
            << " spline ends), " << stats.breakpoints_crossed << " at steps' ends; " << stats.steps
            << " steps, " << stats.rejected << " rejected, " << stats.evaluations
            << " evaluations; error " << error << " rad against 1e-11, energy within "
            << worst_energy << " J of " << energy0 << " J\n";
}

}  // namespace
}  // namespace sinew::engine

// rk45 and the jumps of the accelerations where a coordinate crosses the end of a cubic spline
// of its joint (past it OpenSim's SimmSpline extrapolates linearly, so f'' and the
// velocity-product terms jump): Rajagopal2016's walker knees and patella couplers, whose
// SimmSplines span knee angles 0 to 2.0944 rad. A step straddling such a jump is retried to
// end just short of it, and the next starts by crossing it (System::curvature_jumps).
#include <gtest/gtest.h>
#include <sinew/engine/energy.h>

#include <cmath>
#include <iostream>
#include <map>
#include <utility>

#include "engine/hung_skeleton.h"

namespace sinew::engine {
namespace {

TEST(CurvatureJumpTest, SplineEndsOfRajagopalsKneesAreListed) {
  const testing::HungSkeleton hung =
      testing::MakeHungSkeleton(testing::kRajagopal2016HungFile, true, 1.0);
  const System& system = *hung.system;
  std::map<std::string, std::vector<double>> listed;
  for (const auto& [coordinate, value] : system.curvature_jumps()) {
    listed[system.coordinates()[coordinate].name].push_back(value);
  }
  // Each knee's rotation and translation splines (knee_angle_*), the patellae's
  // (knee_angle_*_beta), and the couplers' functions of the knee angles: both ends, 0 and
  // 2.0944 rad, listed once per coordinate.
  for (const char* name :
       {"knee_angle_r", "knee_angle_l", "knee_angle_r_beta", "knee_angle_l_beta"}) {
    ASSERT_EQ(listed[name].size(), 2u) << name;
    EXPECT_EQ(listed[name][0], 0.0) << name;
    EXPECT_NEAR(listed[name][1], 2.0944, 1e-12) << name;
  }
  EXPECT_EQ(listed.size(), 4u);  // the pelvis is locked; no other joint has a spline
}

TEST(CurvatureJumpTest, HungRajagopalCrossesEachKneeSplineEndAtAStepsEnd) {
  // The hung skeleton's second (BM_Rajagopal2016HungOneSecond), its right knee crossing 0 at
  // 10.7 and 12.7 rad/s. Reported every millisecond: every crossing seen between two reports
  // is one crossed at a step's end, and the run keeps the accuracy's error against a tight
  // reference and the mechanical energy (gravity alone acts).
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
  long seen = 0;
  for (int ms = 1; ms <= 1000; ++ms) {
    const State before = state;
    integrator->StepTo(state, 1e-3 * ms);
    for (const auto& [coordinate, value] : system.curvature_jumps()) {
      if ((before.q[coordinate] - value) * (state.q[coordinate] - value) < 0.0) ++seen;
    }
    worst_energy = std::max(worst_energy, std::abs(CalcMechanicalEnergy(system, state) - energy0));
  }
  const IntegratorStats& stats = integrator->stats();
  EXPECT_GE(seen, 4);  // the right knee and its patella, twice
  EXPECT_EQ(stats.curvature_jumps, seen);
  const State reference = testing::RunHung(hung, "rk45", 1e-11, nullptr);
  double error = 0.0;
  for (int c = 0; c < system.num_coordinates(); ++c) {
    error = std::max(error, std::abs(state.q[c] - reference.q[c]));
  }
  // rk45's global error at accuracy 1e-7 over the second is of the order of 10 accuracies.
  EXPECT_LT(error, 1e-6);
  EXPECT_LT(worst_energy, 1e-6 * std::abs(energy0));
  std::cout << "hung Rajagopal2016 at 1e-7: " << seen << " spline ends crossed, "
            << stats.curvature_jumps << " at steps' ends; " << stats.steps << " steps, "
            << stats.rejected << " rejected, " << stats.evaluations << " evaluations; error "
            << error << " rad against 1e-11, energy within " << worst_energy << " J of " << energy0
            << " J\n";
}

}  // namespace
}  // namespace sinew::engine

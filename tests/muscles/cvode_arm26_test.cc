// The implicit "cvode" and "cvode-gmres" integrators on a real muscle model: arm26 (6 Thelen
// muscles on wrapped paths, OpenSim's Forward test controls and initial states) agrees with
// rk45 at tight accuracy.
#include <gtest/gtest.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/kkt.h>
#include <sinew/engine/state_vector.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "muscles/arm26_model.h"

namespace sinew::muscles {
namespace {

TEST(CvodeArm26Test, AgreesWithRk45AtTightAccuracy) {
  auto arm = LoadArm26();
  const engine::System& system = *arm->system;
  // rk45 at 1e-10, a hundred times tighter than the runs checked, every 0.1 s over 0.5 s.
  std::vector<engine::State> reference;
  engine::State state = arm->state;
  auto rk45 = engine::MakeIntegrator("rk45", system, {.accuracy = 1e-10});
  rk45->SetController(arm->parser.GetController());
  for (int i = 1; i <= 5; ++i) {
    rk45->StepTo(state, 0.1 * i);
    reference.push_back(state);
  }
  const engine::KktSolver kkt(system);
  const double size = engine::StateVector(system, kkt).size();
  const double accuracy = 1e-8;
  for (const char* name : {"cvode", "cvode-gmres", "cvode-gmres-bd"}) {
    state = arm->state;
    auto cvode = engine::MakeIntegrator(name, system, {.accuracy = accuracy});
    cvode->SetController(arm->parser.GetController());
    double q_diff = 0.0, u_diff = 0.0, z_diff = 0.0;
    for (const engine::State& expected : reference) {
      cvode->StepTo(state, expected.t);
      q_diff = std::max(q_diff, (state.q - expected.q).lpNorm<Eigen::Infinity>());
      u_diff = std::max(u_diff, (state.u - expected.u).lpNorm<Eigen::Infinity>());
      z_diff = std::max(z_diff, (state.z - expected.z).lpNorm<Eigen::Infinity>());
    }
    // Each run holds its local error per step to its accuracy with a unit floor (CVODE in the
    // RMS norm of its vector, so a component's below sqrt(size) x accuracy); the arm's motion
    // over 0.5 s, driven by the controls, does not amplify errors much, so the global
    // difference stays below steps x that local bound. Speeds (up to ~10 rad/s) and fiber
    // lengths (~0.1 m) have the same unit floor.
    const double bound = std::sqrt(size) * static_cast<double>(cvode->stats().steps) * accuracy;
    EXPECT_LT(q_diff, bound) << name;
    EXPECT_LT(u_diff, bound) << name;
    EXPECT_LT(z_diff, bound) << name;
    std::printf(
        "arm26 (n = %.0f) over 0.5 s: %s at %.0e: %ld steps, %ld evaluations; rk45 at 1e-10: %ld "
        "steps; max |dq| %.2g rad, |du| %.2g rad/s, |dz| %.2g\n",
        size, name, accuracy, cvode->stats().steps, cvode->stats().evaluations, rk45->stats().steps,
        q_diff, u_diff, z_diff);
  }
}

}  // namespace
}  // namespace sinew::muscles

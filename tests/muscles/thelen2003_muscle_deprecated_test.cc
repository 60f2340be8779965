// Thelen2003Muscle_Deprecated's equilibrium (OpenSim's computeIsometricForce for the class):
// forces balanced to OpenSim's 0.01 N over a range of path lengths and activations, the
// short-path rule, and a muscle at equilibrium staying there under constant excitation.
// OpenSim's own equilibrium fiber lengths (arm26 in the CMC tutorial's runs) are compared in
// arm26_tutorial_forward_test.cc.
#include <gtest/gtest.h>
#include <sinew/muscles/thelen2003_muscle_deprecated.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "muscles/deprecated_equilibrium_check.h"

namespace sinew::muscles {
namespace {

Thelen2003DeprecatedParameters Parameters() {
  Thelen2003DeprecatedParameters p;
  p.muscle.max_isometric_force = 500.0;
  p.muscle.optimal_fiber_length = 0.12;
  p.muscle.tendon_slack_length = 0.27;
  p.muscle.pennation_angle_at_optimal = 0.2;
  return p;
}

// From a nearly slack tendon to a fiber stretched past the passive curve's linear part, at
// activations from 0 to 1: the balance OpenSim's iteration stops at, or, where none exists
// with the tendon at or beyond its slack length, the tendon held at slack.
TEST(Thelen2003MuscleDeprecatedTest, EquilibriumBalancesTheForcesToOpenSimsLimit) {
  const Thelen2003MuscleDeprecated muscle(Parameters());
  const double width = 0.12 * std::sin(0.2);
  int balanced = 0, slack = 0;
  for (double activation : {0.0, 0.01, 0.3, 1.0}) {
    for (int step = 0; step <= 30; ++step) {
      const double length = 0.30 + 0.01 * step;
      VecX z(2);
      z << activation, 0.0;
      const EquilibriumStatus status = muscle.Equilibrate({length, 0.0}, "musc", z);
      EXPECT_GT(z[1], 0.0);
      if (status == EquilibriumStatus::kBalanced) {
        EXPECT_LE(std::abs(muscle.IsometricImbalance(activation, z[1], length)), 0.01)
            << activation << " " << length;
        ++balanced;
        continue;
      }
      // The tendon at slack, the fiber across the rest of the path at constant width; the
      // slack tendon's small stiffness (0.001 Fiso at zero strain) pulls harder than the
      // fiber, which could only balance it longer (a tendon shorter than slack).
      ASSERT_EQ(status, EquilibriumStatus::kTendonAtSlackLength) << activation << " " << length;
      EXPECT_NEAR(z[1], std::hypot(length - 0.27, width), 1e-15);
      EXPECT_GT(muscle.IsometricImbalance(activation, z[1], length), 0.01);
      EXPECT_GT(muscle.IsometricImbalance(activation, z[1] + 1e-4, length), 0.0);
      ++slack;
    }
  }
  std::printf("%d balanced, %d with the tendon at slack\n", balanced, slack);
  EXPECT_EQ(balanced + slack, 4 * 31);
  EXPECT_GE(balanced, 4 * 31 - 8);
  // A path shorter than the tendon's slack length: no force, the fiber as long as the muscle
  // is wide (OpenSim's answer).
  VecX z(2);
  z << 0.5, 0.0;
  muscle.Equilibrate({0.2, 0.0}, "musc", z);
  EXPECT_DOUBLE_EQ(z[1], 0.12 * std::sin(0.2));
}

TEST(Thelen2003MuscleDeprecatedTest, NonFiniteInputsAreErrorsNamingTheMuscle) {
  const Thelen2003MuscleDeprecated muscle(Parameters());
  VecX z(2);
  z << std::nan(""), 0.0;
  try {
    muscle.Equilibrate({0.4, 0.0}, "/forceset/musc", z);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/forceset/musc"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("not finite"), std::string::npos) << e.what();
  }
}

// deprecated_equilibrium_check.h says what is checked and why. The activation's equation
// (u - a) / tau holds it, and the force-velocity relation gives zero fiber velocity at the
// exact balance.
TEST(Thelen2003MuscleDeprecatedTest, MuscleAtEquilibriumStaysThereUnderConstantExcitation) {
  ExpectEquilibriumHoldsUnderConstantExcitation<Thelen2003MuscleDeprecated>(
      std::string(R"(<Thelen2003Muscle_Deprecated name="musc">)") + kPath +
      R"(<max_isometric_force>500</max_isometric_force>
<optimal_fiber_length>0.12</optimal_fiber_length><tendon_slack_length>0.27</tendon_slack_length>
<pennation_angle_at_optimal>0.2</pennation_angle_at_optimal></Thelen2003Muscle_Deprecated>)");
}

}  // namespace
}  // namespace sinew::muscles

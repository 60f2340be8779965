// Thelen2003Muscle's curves against the equations of Thelen (2003), J Biomech Eng 125:70-77,
// written out here independently of the library: the Gaussian active force-length curve (his
// eq. 2), the exponential passive curve (eq. 3), the tendon's exponential toe and linear
// region (eq. 4, whose constants e_toe and k_lin the paper rounds to 0.609 e0 and 1.712/e0;
// the test solves the two conditions that define them instead), and the force-velocity
// relation (eq. 6) with its activation-dependent maximum velocity.
#include <gtest/gtest.h>
#include <sinew/muscles/first_order_activation.h>
#include <sinew/muscles/thelen2003_curves.h>

#include <cmath>

namespace sinew::muscles {
namespace {

// arm26's TRIlong shape parameters (not the defaults, so the test sees them used).
Thelen2003CurveParameters Arm26Curves() {
  Thelen2003CurveParameters p;
  p.FmaxTendonStrain = 0.033;
  p.FmaxMuscleStrain = 0.6;
  p.KshapeActive = 0.5;
  p.KshapePassive = 4.0;
  p.Af = 0.3;
  p.Flen = 1.8;
  return p;
}

TEST(ThelenCurvesTest, ForceLengthCurvesAreThelensEquations) {
  const Thelen2003CurveParameters p = Arm26Curves();
  for (double lceN = 0.3; lceN <= 1.8; lceN += 0.05) {
    const double gaussian = std::exp(-(lceN - 1) * (lceN - 1) / 0.5);
    EXPECT_NEAR(ThelenActiveForceLength(p, lceN), gaussian, 1e-15) << lceN;
    const double passive =
        lceN > 1 ? (std::exp(4.0 * (lceN - 1) / 0.6) - 1) / (std::exp(4.0) - 1) : 0.0;
    EXPECT_NEAR(ThelenPassiveForceLength(p, lceN), passive, 1e-14) << lceN;
    // Slopes against central differences (h = 1e-6: truncation ~1e-12 on these curves).
    const double h = 1e-6;
    if (std::abs(lceN - 1.0) > 2 * h) {
      EXPECT_NEAR(
          ThelenPassiveForceLengthSlope(p, lceN),
          (ThelenPassiveForceLength(p, lceN + h) - ThelenPassiveForceLength(p, lceN - h)) / (2 * h),
          1e-7);
    }
    EXPECT_NEAR(
        ThelenActiveForceLengthSlope(p, lceN),
        (ThelenActiveForceLength(p, lceN + h) - ThelenActiveForceLength(p, lceN - h)) / (2 * h),
        1e-8);
  }
  // The passive force reaches 1 at FmaxMuscleStrain.
  EXPECT_NEAR(ThelenPassiveForceLength(p, 1.6), 1.0, 1e-15);
}

TEST(ThelenCurvesTest, TendonToeAndLinearRegionMeetSmoothlyAtTheForceOne) {
  const Thelen2003CurveParameters p = Arm26Curves();
  const double e0 = p.FmaxTendonStrain, k_toe = 3.0, f_toe = 0.33;
  // Solve for the toe strain: the linear region through (e_toe, F_toe) with the toe's slope
  // there reaches 1 at e0: F_toe + k_toe F_toe exp(k_toe)/((exp(k_toe) - 1) e_toe) (e0 - e_toe)
  // = 1.
  auto residual = [&](double e_toe) {
    const double slope = f_toe * k_toe * std::exp(k_toe) / ((std::exp(k_toe) - 1) * e_toe);
    return f_toe + slope * (e0 - e_toe) - 1.0;
  };
  double lo = 0.1 * e0, hi = 0.99 * e0;
  for (int i = 0; i < 200; ++i) (residual(0.5 * (lo + hi)) > 0 ? lo : hi) = 0.5 * (lo + hi);
  const double e_toe = 0.5 * (lo + hi);
  const double k_lin = f_toe * k_toe * std::exp(k_toe) / ((std::exp(k_toe) - 1) * e_toe);
  // The paper's rounded constants.
  EXPECT_NEAR(e_toe / e0, 0.609, 5e-4);
  EXPECT_NEAR(k_lin * e0, 1.712, 5e-4);
  for (double strain = -0.01; strain <= 0.06; strain += 0.0013) {
    double expected = 0.0;
    if (strain > e_toe) {
      expected = k_lin * (strain - e_toe) + f_toe;
    } else if (strain > 0) {
      expected = f_toe / (std::exp(k_toe) - 1) * (std::exp(k_toe * strain / e_toe) - 1);
    }
    EXPECT_NEAR(ThelenTendonForceLength(p, 1.0 + strain), expected, 1e-13) << strain;
  }
  EXPECT_NEAR(ThelenTendonForceLength(p, 1.0 + e0), 1.0, 1e-13);
  // Slope continuous at the toe strain.
  EXPECT_NEAR(ThelenTendonForceLengthSlope(p, 1.0 + e_toe - 1e-12),
              ThelenTendonForceLengthSlope(p, 1.0 + e_toe + 1e-12), 1e-8);
}

TEST(ThelenCurvesTest, ForceVelocityIsThelensEquationWithLinearEnds) {
  const Thelen2003CurveParameters p = Arm26Curves();
  for (double a : {0.05, 0.4, 1.0}) {
    for (double fal : {0.5, 1.0}) {
      const double afl = a * fal;
      for (double force = 0.02 * afl; force < 0.95 * 1.8 * afl; force += 0.07 * afl) {
        // Thelen's eq. 6, velocity normalized by the maximum contraction velocity.
        const double b = force <= afl ? afl + force / p.Af
                                      : (2 + 2 / p.Af) * (afl * p.Flen - force) / (p.Flen - 1);
        const double v = (0.25 + 0.75 * a) * (force - afl) / b;
        EXPECT_NEAR(ThelenFiberVelocity(p, a, fal, force), v, 1e-14) << a << " " << force;
        // The inverse: the multiplier fv = force / (a fal) at that velocity.
        EXPECT_NEAR(ThelenForceVelocity(p, a, fal, v), force / afl, 1e-10);
      }
      // Beyond the ends the relation is the tangent line: value and slope continuous.
      for (double end : {0.0, 0.95 * 1.8 * afl}) {
        const double inside = end == 0.0 ? 1e-9 : end - 1e-9;
        const double outside = end == 0.0 ? -1e-9 : end + 1e-9;
        EXPECT_NEAR(ThelenFiberVelocity(p, a, fal, inside), ThelenFiberVelocity(p, a, fal, outside),
                    1e-6);
        EXPECT_NEAR(ThelenFiberVelocitySlope(p, a, fal, end + (end == 0.0 ? -0.5 : 0.5) * afl),
                    ThelenFiberVelocitySlope(p, a, fal, outside), 1e-12);
      }
      // Isometric at the isometric force.
      EXPECT_EQ(ThelenFiberVelocity(p, a, fal, afl), 0.0);
    }
  }
}

TEST(ThelenCurvesTest, ActivationTimeConstantsFollowActivation) {
  const FirstOrderActivation act{0.01, 0.04, 0.01};
  // Rising: tau = 0.01 (0.5 + 1.5 a); falling: tau = 0.04 / (0.5 + 1.5 a).
  EXPECT_NEAR(act.CalcDerivative(0.2, 0.7), 0.5 / (0.01 * 0.8), 1e-12);
  EXPECT_NEAR(act.CalcDerivative(0.6, 0.1), -0.5 / (0.04 / 1.4), 1e-12);
  // Below the minimum activation the activation counts as the minimum.
  EXPECT_NEAR(act.CalcDerivative(0.0, 0.5), 0.49 / (0.01 * 0.515), 1e-12);
}

}  // namespace
}  // namespace sinew::muscles

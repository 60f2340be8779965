// Schutte1993Muscle_Deprecated's pure functions: its default curves through the knots OpenSim's
// constructor gives them, the exponential passive curve a file without one gets, the file's own
// curves replacing the defaults, and the fiber velocity against the damped Hill relation it
// inverts (written out here from Schutte's shortening and lengthening hyperbolas).
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/io/osim_reader.h>
#include <sinew/muscles/simm_muscle_spec.h>

#include <cmath>
#include <string>

#include "slider_model.h"

namespace sinew::muscles {
namespace {

TEST(Schutte1993CurvesTest, DefaultCurvesPassThroughOpenSimsKnots) {
  const Schutte1993Muscle muscle(Schutte1993Parameters{});
  // Tendon: strain -> force, 0 for a slack tendon.
  const double strains[] = {0.00131, 0.00431, 0.00731, 0.0103, 0.0123};
  const double forces[] = {0.0108, 0.0435, 0.0915, 0.161, 0.227};
  for (int k = 0; k < 5; ++k) EXPECT_NEAR(muscle.TendonForce(strains[k]), forces[k], 1e-13);
  EXPECT_EQ(muscle.TendonForce(-0.01), 0.0);
  // Active force-length.
  EXPECT_NEAR(muscle.ActiveForceLength(1.045), 0.993333, 1e-13);
  EXPECT_NEAR(muscle.ActiveForceLength(0.62875), 0.636667, 1e-13);
  EXPECT_NEAR(muscle.ActiveForceLength(1.43875), 0.246667, 1e-13);
  // Without a passive curve in the file: exp(8 (l - 1)) / exp(4), which is 1 at l = 1.5.
  EXPECT_NEAR(muscle.PassiveForce(1.5), 1.0, 1e-15);
  EXPECT_NEAR(muscle.PassiveForce(1.0), std::exp(-4.0), 1e-16);
  EXPECT_NEAR(muscle.PassiveForce(0.8), std::exp(-1.6 - 4.0), 1e-16);
}

TEST(Schutte1993CurvesTest, TheFilesCurvesAndPropertiesReplaceTheDefaults) {
  // OpenSim 4's layout (<SimmSpline name="...">) with wrist.osim's passive curve.
  const std::string muscle_text =
      std::string(R"(<Schutte1993Muscle_Deprecated name="musc">)") + kPath +
      R"(<max_isometric_force>59.7</max_isometric_force><optimal_fiber_length>0.0628</optimal_fiber_length>
<tendon_slack_length>0.2185</tendon_slack_length><pennation_angle_at_optimal>0.0541</pennation_angle_at_optimal>
<time_scale>0.2</time_scale><activation1>5</activation1><activation2>2</activation2><damping>0.05</damping>
<SimmSpline name="passive_force_length_curve">
<x> -35 0.998 0.999 1.15 1.25 1.35 1.45 1.55 1.65 1.75 1.7501 1.7502 35</x>
<y> 0 0 0 0 0.035 0.12 0.26 0.55 1.17 2 2 2 2</y></SimmSpline>
</Schutte1993Muscle_Deprecated>)";
  const model::ModelSpec spec = io::ReadOsimString(SliderModel(muscle_text, true), "m.osim");
  const Schutte1993Muscle muscle = ReadSchutte1993Muscle(spec, spec.forces.at(0));
  EXPECT_NEAR(muscle.PassiveForce(1.45), 0.26, 1e-13);
  EXPECT_NEAR(muscle.PassiveForce(1.55), 0.55, 1e-13);
  EXPECT_NEAR(muscle.PassiveForce(1.15), 0.0, 1e-13);
  const Schutte1993Parameters& p = muscle.parameters();
  EXPECT_EQ(p.time_scale, 0.2);
  EXPECT_EQ(p.damping, 0.05);
  EXPECT_EQ(p.muscle.pennation_angle_at_optimal, 0.0541);
  // da/dt = (u - a) (activation1 u + activation2) / time_scale rising, (u - a) activation2 /
  // time_scale falling.
  EXPECT_NEAR(muscle.ActivationRate(0.2, 0.6), 0.4 * (5 * 0.6 + 2) / 0.2, 1e-14);
  EXPECT_NEAR(muscle.ActivationRate(0.6, 0.2), -0.4 * 2 / 0.2, 1e-14);
}

TEST(Schutte1993CurvesTest, OldFilesPennationAngleAndIgnoreFlags) {
  // Format 20301 and older: pennation_angle (OpenSim renames it), curves inside their property.
  std::string text = SliderModel(
      std::string(R"(<Schutte1993Muscle name="musc">)") + kPath +
          R"(<pennation_angle>0.2</pennation_angle><tendon_force_length_curve><NaturalCubicSpline>
<x>0 0.01 0.02</x><y>0 0.5 1</y></NaturalCubicSpline></tendon_force_length_curve></Schutte1993Muscle>)",
      true);
  text.replace(text.find("40000"), 5, "20301");
  model::ModelSpec spec = io::ReadOsimString(text, "old.osim");
  const Schutte1993Muscle muscle = ReadSchutte1993Muscle(spec, spec.forces.at(0));
  EXPECT_EQ(muscle.parameters().muscle.pennation_angle_at_optimal, 0.2);
  EXPECT_NEAR(muscle.TendonForce(0.015), 0.75, 1e-14);  // the file's straight line
  // OpenSim refuses either ignore flag for this class: so does Sinew, with file, line, muscle.
  spec = io::ReadOsimString(
      SliderModel(std::string(R"(<Schutte1993Muscle_Deprecated name="musc">)") + kPath +
                      "\n<ignore_tendon_compliance>true</ignore_tendon_compliance>"
                      "</Schutte1993Muscle_Deprecated>",
                  true),
      "flags.osim");
  try {
    ReadSchutte1993Muscle(spec, spec.forces.at(0));
    FAIL() << "no error";
  } catch (const Error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("flags.osim:"), std::string::npos) << message;
    EXPECT_NE(message.find("/forceset/musc"), std::string::npos) << message;
    EXPECT_NE(message.find("ignore_tendon_compliance"), std::string::npos) << message;
  }
}

// Schutte's force-velocity relation with damping d, F the velocity-dependent normalized force
// and v the normalized fiber velocity (lengthening positive): shortening (v < 0)
// F = a fal kv (1 + v) / (kv - v) + d v with kv = 0.15; lengthening
// F = a fal (1.4 v + s) / (v + s) + d v with s = 0.13 kv / (kv + 1). Both give a fal at v = 0.
double HillForce(double a, double fal, double d, double v) {
  const double kv = 0.15, s = 0.13 * kv / (kv + 1.0);
  if (v < 0.0) return a * fal * kv * (1.0 + v) / (kv - v) + d * v;
  return a * fal * (1.4 * v + s) / (v + s) + d * v;
}

TEST(Schutte1993CurvesTest, FiberVelocitySolvesTheDampedHillRelation) {
  for (double damping : {0.05, 0.1}) {
    Schutte1993Parameters p;
    p.damping = damping;
    const Schutte1993Muscle muscle(p);
    for (double a : {0.02, 0.3, 1.0}) {
      for (double fal : {0.25, 1.0}) {
        EXPECT_EQ(muscle.FiberVelocity(a, fal, a * fal), 0.0);  // isometric
        for (double f = 0.0; f <= 2.0 * a * fal; f += 0.05 * a * fal) {
          const double v = muscle.FiberVelocity(a, fal, f);
          EXPECT_NEAR(HillForce(a, fal, damping, v), f, 1e-13) << a << " " << fal << " " << f;
          EXPECT_EQ(v < 0.0, f < a * fal) << f;  // shortening below the isometric force
        }
      }
    }
  }
}

}  // namespace
}  // namespace sinew::muscles

// Blankevoort1991Ligament against closed forms written out here: the force-strain law in its
// slack, toe and linear regions (force and slope continuous at the transition), the damping's
// sign and fade-in, the potential energy as the integral of the force, the generalized force
// -tension dL/dq on a two-segment path, energy conservation of a pendulum hung by a ligament,
// bad parameters refused by file, line and component, and lenhart2015's 76 ligaments.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/energy.h>
#include <sinew/engine/integrator.h>
#include <sinew/io/osim_reader.h>
#include <sinew/muscles/blankevoort_ligament.h>
#include <sinew/opensim/parser.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "corpus.h"

namespace sinew::muscles {
namespace {

// Independent form of the law: toe F = k e^2 / (2 e_t); linear F = F(e_t) + k (e - e_t).
double ClosedFormForce(double k, double e_t, double e) {
  if (e <= 0) return 0;
  const double toe_end = k * e_t / 2;
  return e < e_t ? k / (2 * e_t) * e * e : toe_end + k * (e - e_t);
}

TEST(BlankevoortLawTest, SlackToeAndLinearRegionsMatchTheClosedForm) {
  const BlankevoortParameters p{.linear_stiffness = 800,
                                .transition_strain = 0.05,
                                .damping_coefficient = 0,
                                .slack_length = 0.04};
  for (double e : {-0.2, -1e-9, 0.0, 1e-4, 0.01, 0.03, 0.0499, 0.05, 0.07, 0.3}) {
    EXPECT_NEAR(BlankevoortSpringForce(p, e), ClosedFormForce(800, 0.05, e), 1e-12) << e;
  }
  // At the transition the force is k e_t / 2 from both sides, and so is the slope k.
  const double d = 1e-7;
  EXPECT_NEAR(BlankevoortSpringForce(p, 0.05 - d), 800 * 0.05 / 2, 800 * 2 * d);
  EXPECT_NEAR(BlankevoortSpringForce(p, 0.05 + d), 800 * 0.05 / 2, 800 * 2 * d);
  const double h = 1e-5;
  const double slope_below =
      (BlankevoortSpringForce(p, 0.05 - h) - BlankevoortSpringForce(p, 0.05 - 2 * h)) / h;
  const double slope_above =
      (BlankevoortSpringForce(p, 0.05 + 2 * h) - BlankevoortSpringForce(p, 0.05 + h)) / h;
  EXPECT_NEAR(slope_below, 800, 800 * 1e-3);
  EXPECT_NEAR(slope_above, 800, 1e-6);
  // Through the path: strain = L / L0 - 1.
  const LigamentForces f = CalcBlankevoortForces(p, {.length = 0.046, .lengthening_speed = 0});
  EXPECT_NEAR(f.strain, 0.15, 1e-12);
  EXPECT_NEAR(f.total, ClosedFormForce(800, 0.05, 0.15), 1e-9);
}

TEST(BlankevoortLawTest, DampingOnlyPullsWhileStretchedAndLengtheningAndFadesIn) {
  const BlankevoortParameters p{.linear_stiffness = 500,
                                .transition_strain = 0.06,
                                .damping_coefficient = 3,
                                .slack_length = 0.1};
  // Stretched (strain 0.1) and lengthening at 0.02 m/s: strain rate 0.2 /s, damping c * 0.2.
  LigamentForces f = CalcBlankevoortForces(p, {.length = 0.11, .lengthening_speed = 0.02});
  EXPECT_NEAR(f.strain_rate, 0.2, 1e-12);
  EXPECT_NEAR(f.damping, 3 * 0.2, 1e-12);
  EXPECT_NEAR(f.total, ClosedFormForce(500, 0.06, 0.1) + 0.6, 1e-9);
  // Shortening: no damping at all (never a push), the total is the spring alone.
  f = CalcBlankevoortForces(p, {.length = 0.11, .lengthening_speed = -5});
  EXPECT_EQ(f.damping, 0.0);
  EXPECT_NEAR(f.total, ClosedFormForce(500, 0.06, 0.1), 1e-9);
  // Slack and lengthening fast: nothing.
  f = CalcBlankevoortForces(p, {.length = 0.099, .lengthening_speed = 10});
  EXPECT_EQ(f.total, 0.0);
  // Strain 0.005, half-way through the fade-in over 0..0.01: the quintic smooth step
  // 10 s^3 - 15 s^4 + 6 s^5 is 1/2 at s = 1/2, and 0.104 at s = 0.2.
  f = CalcBlankevoortForces(p, {.length = 0.1005, .lengthening_speed = 0.01});
  EXPECT_NEAR(f.damping, 3 * 0.1 * 0.5, 1e-12);
  f = CalcBlankevoortForces(p, {.length = 0.1002, .lengthening_speed = 0.01});
  EXPECT_NEAR(f.damping, 3 * 0.1 * (10 * 0.008 - 15 * 0.0016 + 6 * 0.00032), 1e-12);
  // Over a sweep of lengths and speeds the total is never negative.
  for (double length = 0.09; length < 0.13; length += 0.001) {
    for (double speed : {-1.0, -0.01, 0.0, 0.01, 1.0}) {
      EXPECT_GE(CalcBlankevoortForces(p, {length, speed}).total, 0.0);
    }
  }
}

TEST(BlankevoortLawTest, PotentialEnergyIsTheIntegralOfTheSpringForceOverLength) {
  const BlankevoortParameters p{.linear_stiffness = 800,
                                .transition_strain = 0.05,
                                .damping_coefficient = 1,
                                .slack_length = 0.04};
  const auto energy = [&](double length) {
    return BlankevoortPotentialEnergy(p, length / p.slack_length - 1);
  };
  EXPECT_EQ(energy(0.039), 0.0);
  // dV/dL = F by central differences, in every region.
  const double h = 1e-7;
  for (double e : {-0.01, 0.001, 0.02, 0.049, 0.051, 0.1, 0.4}) {
    const double length = p.slack_length * (1 + e);
    const double dV_dL = (energy(length + h) - energy(length - h)) / (2 * h);
    EXPECT_NEAR(dV_dL, ClosedFormForce(800, 0.05, e), 1e-5) << e;
  }
  // And V(L) by a Simpson quadrature of F from the slack length.
  const double length_end = p.slack_length * 1.2;
  const int n = 2000;
  const double dl = (length_end - p.slack_length) / n;
  double integral = 0;
  for (int i = 0; i <= n; ++i) {
    const double weight = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
    integral += weight * ClosedFormForce(800, 0.05, i * dl / p.slack_length);
  }
  EXPECT_NEAR(energy(length_end), integral * dl / 3, 1e-9);
}

// A 1 kg pendulum (pin about ground's z, mass centre 0.5 m below) hung by a ligament from
// ground (0.4, 0.1) through a via point on the arm at (0.1, -0.2) to (0, -0.4) on the arm.
std::string PendulumModel(const std::string& ligament_properties) {
  return std::string(R"(<OpenSimDocument Version="40000"><Model name="pendulum">
<gravity>0 -9.80665 0</gravity><Ground name="ground"/>
<BodySet><objects><Body name="arm"><mass>1</mass><mass_center>0 -0.5 0</mass_center>
<inertia>0.01 0.01 0.01 0 0 0</inertia></Body></objects></BodySet>
<JointSet><objects><PinJoint name="pin"><socket_parent_frame>/ground</socket_parent_frame>
<socket_child_frame>/bodyset/arm</socket_child_frame>
<coordinates><Coordinate name="theta"><default_value>0.3</default_value><default_speed_value>-1</default_speed_value></Coordinate></coordinates>
</PinJoint></objects></JointSet>
<ForceSet><objects><Blankevoort1991Ligament name="lig"><GeometryPath><PathPointSet><objects>
<PathPoint name="p1"><socket_parent_frame>/ground</socket_parent_frame><location>0.4 0.1 0</location></PathPoint>
<PathPoint name="p2"><socket_parent_frame>/bodyset/arm</socket_parent_frame><location>0.1 -0.2 0</location></PathPoint>
<PathPoint name="p3"><socket_parent_frame>/bodyset/arm</socket_parent_frame><location>0 -0.4 0</location></PathPoint>
</objects></PathPointSet></GeometryPath>
)") + ligament_properties +
         R"(
</Blankevoort1991Ligament></objects></ForceSet></Model></OpenSimDocument>)";
}

struct Parsed {
  opensim::OpenSimParser parser;
  std::unique_ptr<engine::System> system;
};

std::unique_ptr<Parsed> Parse(const model::ModelSpec& spec) {
  auto parsed = std::make_unique<Parsed>();
  parsed->system = std::make_unique<engine::System>(spec.gravity);
  parsed->parser.ParseSpec(*parsed->system, spec);
  parsed->system->Finalize();
  return parsed;
}

std::unique_ptr<Parsed> ParsePendulum(const std::string& properties) {
  return Parse(io::ReadOsimString(PendulumModel(properties), "ligament_test.osim"));
}

// The ligament's record values at `state`: spring, damping, total, length, speed, strain, rate.
std::vector<double> Record(const engine::System& system, const engine::State& state) {
  std::vector<double> values;
  system.force_elements()[0]->CalcRecordValues(system.MakeForceContext(0, state), values);
  return values;
}

const char* kProperties =
    "<linear_stiffness>300</linear_stiffness><transition_strain>0.06</transition_strain>"
    "<slack_length>0.45</slack_length>";

TEST(BlankevoortLigamentTest, GeneralizedForceIsMinusTensionTimesDLengthDq) {
  auto parsed =
      ParsePendulum(std::string(kProperties) + "<damping_coefficient>2</damping_coefficient>");
  const engine::System& system = *parsed->system;
  ASSERT_EQ(system.force_elements().size(), 1u);
  const std::vector<std::string> labels = system.force_elements()[0]->RecordLabels(system);
  ASSERT_EQ(labels.size(), 7u);
  EXPECT_EQ(labels[2], "lig.force_total");
  engine::State state = engine::MakeDefaultState(system);
  const double u = 0.7;
  double max_tension = 0;
  for (double theta : {-0.2, 0.1, 0.4, 0.8}) {
    // dL/dq by central differences of the recorded length.
    const double h = 1e-6;
    engine::SetCoordinateValue(system, state, "theta", theta + h);
    const double length_plus = Record(system, state)[3];
    engine::SetCoordinateValue(system, state, "theta", theta - h);
    const double length_minus = Record(system, state)[3];
    const double dL_dq = (length_plus - length_minus) / (2 * h);
    engine::SetCoordinateValue(system, state, "theta", theta);
    engine::SetCoordinateSpeed(system, state, "theta", u);
    const std::vector<double> record = Record(system, state);
    const double tension = record[2];
    max_tension = std::max(max_tension, tension);
    // One coordinate: the loads' power is Q u.
    const double Q = engine::CalcForcePower(system, state, 0) / u;
    EXPECT_NEAR(Q, -tension * dL_dq, 1e-7 * std::max(1.0, tension)) << theta;
    EXPECT_NEAR(record[4], dL_dq * u, 1e-8) << theta;
    EXPECT_EQ(record[1] > 0, record[5] > 0 && record[4] > 0) << theta;
  }
  EXPECT_GT(max_tension, 10.0);  // the ligament is well stretched at some of the angles
}

TEST(BlankevoortLigamentTest, PendulumHungByAnUndampedLigamentConservesEnergy) {
  auto parsed =
      ParsePendulum(std::string(kProperties) + "<damping_coefficient>0</damping_coefficient>");
  const engine::System& system = *parsed->system;
  auto integrator = engine::MakeIntegrator("rk45", system, {.accuracy = 1e-11});
  engine::State state = engine::MakeDefaultState(system);
  const double energy0 = engine::CalcMechanicalEnergy(system, state);
  double max_strain = -1, min_strain = 1, max_drift = 0;
  for (int i = 1; i <= 200; ++i) {
    integrator->StepTo(state, 0.01 * i);
    const std::vector<double> record = Record(system, state);
    max_strain = std::max(max_strain, record[5]);
    min_strain = std::min(min_strain, record[5]);
    max_drift =
        std::max(max_drift, std::abs(engine::CalcMechanicalEnergy(system, state) - energy0));
  }
  // The swing visits the slack, toe and linear regions.
  EXPECT_LT(min_strain, 0.0);
  EXPECT_GT(max_strain, 0.06);
  EXPECT_LT(max_drift, 1e-6 * std::abs(energy0));
  std::printf("ligament pendulum: strain %.4f..%.4f, energy %.6f J, drift %.3g J\n", min_strain,
              max_strain, energy0, max_drift);
}

TEST(BlankevoortLigamentTest, BadParametersAreRefusedWithFileLineAndComponent) {
  const auto message = [](const std::string& properties) -> std::string {
    try {
      ParsePendulum(properties);
    } catch (const Error& error) {
      return error.what();
    }
    return "no error";
  };
  const std::string negative =
      message("\n<linear_stiffness>-3</linear_stiffness><slack_length>0.45</slack_length>");
  // The error names the property's own line.
  const std::string model = PendulumModel("\n<linear_stiffness>-3</linear_stiffness>");
  const int line = 1 + static_cast<int>(std::count(
                           model.begin(), model.begin() + model.find("<linear_stiffness>"), '\n'));
  EXPECT_NE(negative.find("ligament_test.osim:" + std::to_string(line) + ":"), std::string::npos)
      << negative;
  EXPECT_NE(negative.find("lig"), std::string::npos) << negative;
  EXPECT_NE(negative.find("linear_stiffness"), std::string::npos) << negative;
  for (const char* bad :
       {"<damping_coefficient>-1</damping_coefficient><slack_length>0.45</slack_length>",
        "<transition_strain>0</transition_strain><slack_length>0.45</slack_length>",
        "<slack_length>0</slack_length>", "<linear_stiffness>5</linear_stiffness>"}) {
    EXPECT_NE(message(bad).find("ligament_test.osim:"), std::string::npos) << bad;
  }
}

TEST(BlankevoortLigamentTest, Lenhart2015BuildsEveryLigamentAndSimulates) {
  SINEW_SKIP_WITHOUT_CORPUS();
  const auto file =
      testing::CorpusDir() / "clnsmith/opensim-jam/models/lenhart2015/lenhart2015.osim";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " is not in the corpus";
  const model::ModelSpec spec = io::ReadOsim(file.string());
  const auto in_file = std::count_if(spec.forces.begin(), spec.forces.end(), [](const auto& f) {
    return f.type == "Blankevoort1991Ligament";
  });
  auto parsed = Parse(spec);
  const engine::System& system = *parsed->system;
  int built = 0;
  for (const auto& force : system.force_elements()) {
    built += dynamic_cast<const BlankevoortLigament*>(force.get()) != nullptr;
  }
  EXPECT_EQ(in_file, 76);
  EXPECT_EQ(built, in_file);
  auto integrator = engine::MakeIntegrator("rk45", system, {.accuracy = 1e-5});
  engine::State state = engine::MakeDefaultState(system);
  integrator->StepTo(state, 0.01);
  EXPECT_TRUE(state.q.allFinite());
  EXPECT_TRUE(state.u.allFinite());
}

}  // namespace
}  // namespace sinew::muscles

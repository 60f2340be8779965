// OpenSim's body constraints (WeldConstraint, PointConstraint, PointOnLineConstraint,
// ConstantDistanceConstraint) through the parser, on a model written for these tests
// (tests/data/sinew/constraints.osim): residuals along a simulation, the loads they transmit
// against hand computations and a pin joint, and the assembly of the initial state as OpenSim
// assembles (tests/data/sinew/reach.osim, springs.osim).
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/dynamics.h>
#include <sinew/engine/energy.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/pose.h>
#include <sinew/engine/projection.h>
#include <sinew/engine/reactions.h>
#include <sinew/opensim/constraint_forces_table.h>
#include <sinew/opensim/parser.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

namespace sinew {
namespace {

const std::string kData = SINEW_TEST_DATA_DIR;
constexpr double kG = 9.80665;

// The largest |phi| over every constraint of the system (joints, locks and the model's).
double WorstResidual(const engine::System& system, const engine::State& state) {
  return engine::CalcPositionErrors(system, state).lpNorm<Eigen::Infinity>();
}

// Reads labelled values of the constraint forces table.
struct ForcesRow {
  std::vector<std::string> labels;
  std::vector<double> values;
  double operator()(const std::string& label) const {
    const auto it = std::find(labels.begin(), labels.end(), label);
    EXPECT_NE(it, labels.end()) << label;
    return it == labels.end() ? NAN : values[it - labels.begin()];
  }
  Vec3 Force(const std::string& prefix) const {
    return {(*this)(prefix + "_Fx"), (*this)(prefix + "_Fy"), (*this)(prefix + "_Fz")};
  }
  Vec3 Moment(const std::string& prefix) const {
    return {(*this)(prefix + "_Mx"), (*this)(prefix + "_My"), (*this)(prefix + "_Mz")};
  }
};

ForcesRow CalcForcesRow(const engine::System& system, const engine::State& state,
                        engine::Data& data) {
  ForcesRow row;
  row.labels = opensim::ConstraintForcesLabels(system);
  opensim::ConstraintForcesRow(system, state, nullptr, data, row.values);
  EXPECT_EQ(row.labels.size(), row.values.size());
  return row;
}

// The rotation angle about z of a body turning about z only.
double AngleAboutZ(const engine::BodyState& body) {
  return 2.0 * std::atan2(body.quat_GB.z(), body.quat_GB.w());
}

TEST(ConstraintsTest, ModelConstraintsAreBuiltAndEnforcedOnesOnly) {
  opensim::OpenSimParser parser;
  auto system = parser.Parse(kData + "/sinew/constraints.osim");
  const opensim::Report& report = parser.GetReport();
  for (const char* name : {"weld", "pivot", "rail", "rod"}) {
    ASSERT_NE(report.GetConstraint(name), nullptr) << name;
    EXPECT_NE(report.GetConstraint(name)->constraint, nullptr) << name;
  }
  ASSERT_NE(report.GetConstraint("disabled_weld"), nullptr);
  EXPECT_EQ(report.GetConstraint("disabled_weld")->constraint, nullptr);
  // OpenSim's record labels, in file order: each constrained body (ground too), then nothing
  // else (these constraints act on no coordinate).
  const std::vector<std::string> labels = opensim::ConstraintForcesLabels(*system);
  ASSERT_EQ(labels.size(), 4u * 12u);
  EXPECT_EQ(labels[0], "weld_ground_Fx");
  EXPECT_EQ(labels[11], "weld_welded_Mz");
  EXPECT_EQ(labels[12 + 6], "pivot_point_bob_Fx");
  EXPECT_EQ(labels[47], "rod_rod_bob_Mz");
}

TEST(ConstraintsTest, WeldedBodyCarriesItsWeight) {
  opensim::OpenSimParser parser;
  auto system = parser.Parse(kData + "/sinew/constraints.osim");
  engine::State state = engine::MakeDefaultState(*system);
  EXPECT_LT(WorstResidual(*system, state), 1e-12);
  // The body frame sits on the anchor (0.5 1 0), turned 0.3 rad about z.
  const engine::BodyState& welded = state.bodies[system->FindBody("welded")];
  EXPECT_LT((welded.p_GB - Vec3(0.5, 1, 0)).norm(), 1e-12);
  EXPECT_NEAR(AngleAboutZ(welded), 0.3, 1e-12);
  engine::Data data(*system);
  const ForcesRow row = CalcForcesRow(*system, state, data);
  // It hangs still: the weld applies m g up and the moment that cancels the weight's about the
  // body origin; OpenSim reports the opposite of what the constraint applies.
  const double m = 2.0;
  const Vec3 weight(0, -m * kG, 0);
  const Vec3 r_BoCm = engine::PoseOf(welded).R * Vec3(0.1, -0.2, 0.05);
  const double scale = m * kG;
  EXPECT_LT((row.Force("weld_welded") - weight).norm(), 1e-10 * scale);
  EXPECT_LT((row.Moment("weld_welded") - r_BoCm.cross(weight)).norm(), 1e-10 * scale);
  EXPECT_LT((row.Force("weld_ground") + weight).norm(), 1e-10 * scale);
}

TEST(ConstraintsTest, ConstraintsHoldAndTransmitTheirClosedFormLoadsAlongTheMotion) {
  opensim::OpenSimParser parser;
  auto system = parser.Parse(kData + "/sinew/constraints.osim");
  engine::State state = engine::MakeDefaultState(*system);
  ASSERT_LT(WorstResidual(*system, state), 1e-12);
  // The pin pendulum starts where the assembly put the point-constrained one.
  const int point_bob = system->FindBody("point_bob");
  const int pin_bob = system->FindBody("pin_bob");
  const int line_block = system->FindBody("line_block");
  const int rod_bob = system->FindBody("rod_bob");
  engine::SetCoordinateValue(*system, state, "pin_angle", AngleAboutZ(state.bodies[point_bob]));
  ASSERT_LT(WorstResidual(*system, state), 1e-12);

  engine::IntegratorSettings settings;
  settings.accuracy = 1e-10;
  auto integrator = engine::MakeIntegrator("rk45", *system, settings);
  engine::Data data(*system);
  const double e0 = engine::CalcMechanicalEnergy(*system, state);
  const Vec3 d = Vec3(1, 1, 0).normalized();
  const Vec3 g(0, -kG, 0);
  const Vec3 line_start = state.bodies[line_block].p_GB;
  const Vec3 anchor(0, 3, 2);
  const int pin_joint = system->FindJoint("pin");
  double worst_phi = 0, worst_angle = 0, worst_pivot = 0, worst_rail = 0, worst_slide = 0;
  double worst_rod = 0, worst_energy = 0;
  for (int k = 0; k <= 20; ++k) {
    const double t = 0.05 * k;
    integrator->StepTo(state, t);
    worst_phi = std::max(worst_phi, WorstResidual(*system, state));
    worst_energy =
        std::max(worst_energy, std::abs(engine::CalcMechanicalEnergy(*system, state) - e0));
    const ForcesRow row = CalcForcesRow(*system, state, data);
    // PointConstraint pendulum = PinJoint pendulum: same angle, same load on the bob.
    worst_angle = std::max(worst_angle, std::abs(AngleAboutZ(state.bodies[point_bob]) -
                                                 AngleAboutZ(state.bodies[pin_bob])));
    const Vec3 pin_force =
        engine::CalcJointReaction(*system, state, data.accelerations, data.kkt, pin_joint)
            .tail<3>();
    worst_pivot = std::max(worst_pivot, (-row.Force("pivot_point_bob") - pin_force).norm());
    // PointOnLineConstraint: frictionless slide along d from rest, s = (g . d) t^2 / 2, and the
    // rail carries the weight's normal part: applied -m (g - (g . d) d).
    const double m_block = 3.0;
    const Vec3 expected_position = line_start + 0.5 * g.dot(d) * t * t * d;
    worst_slide = std::max(worst_slide, (state.bodies[line_block].p_GB - expected_position).norm());
    const Vec3 rail_applied = -m_block * (g - g.dot(d) * d);
    worst_rail = std::max(worst_rail, (-row.Force("rail_line_block") - rail_applied).norm());
    // ConstantDistanceConstraint: a point mass on a rod; radially m (-|v|^2 / L) = m g . e - T
    // with e the unit vector from the anchor: the rod pulls with T = m (|v|^2 / L + g . e).
    const double m_rod = 0.8, L = 0.7;
    const Vec3 e = (state.bodies[rod_bob].p_GB - anchor).normalized();
    const double T = m_rod * (state.bodies[rod_bob].v_GB.squaredNorm() / L + g.dot(e));
    worst_rod = std::max(worst_rod, (-row.Force("rod_rod_bob") - (-T * e)).norm());
  }
  const double steps = static_cast<double>(integrator->stats().steps);
  EXPECT_LT(worst_phi, 1e-8);
  // The two pendulums are integrated in one state with the same steps by equations that differ
  // only in form (an extra constraint on a free body, a pin joint): they differ by rounding
  // (measured 9e-16 rad and 3e-14 N).
  EXPECT_LT(worst_angle, 1e-12);
  EXPECT_LT(worst_pivot, 1e-10 * 1.5 * kG);
  // A constant acceleration along the rail: RK45 integrates the parabola exactly (2e-15 m).
  EXPECT_LT(worst_slide, 1e-12);
  // One state, two routes to the load (multipliers, or the closed form from positions and
  // velocities): rounding, and positions and velocities held to the projection tolerance
  // (measured 4e-15 N and 2e-13 N).
  EXPECT_LT(worst_rail, 1e-12 * 3.0 * kG);
  EXPECT_LT(worst_rod, 1e-11 * 0.8 * kG);
  // Every constraint is ideal (no work): the energy is conserved (scale ~100 J).
  EXPECT_LT(worst_energy, 100.0 * steps * settings.accuracy);
  std::cout << "constraints.osim, 1 s at 1e-10 (" << steps << " steps): residual " << worst_phi
            << ", point vs pin pendulum " << worst_angle << " rad and " << worst_pivot
            << " N, slide " << worst_slide << " m, rail load " << worst_rail << " N, rod load "
            << worst_rod << " N, energy drift " << worst_energy << " J\n";
}

// Real models, passive, with every coordinate given the speed sin(c + 1) (projected onto the
// constraints) so that all joints move: their constraints hold along 0.5 s at accuracy 1e-6.
// Rajagopal2016 and leg6dof9musc couple their patellae to the knees; bouncing_block holds its
// block and foot on ground's y axis with two PointOnLineConstraints (its hip BushingForce and
// its Hunt-Crossley heel contact act); the Hamner full-body
// model (subject02) has no constraints in its file: its joints alone.
TEST(ConstraintsTest, RealModelsSimulatePassivelyWithTheirConstraintsHeld) {
  const std::vector<std::pair<std::string, int>> models = {
      {"opensim-org/opensim-models/Models/Rajagopal/Rajagopal2016.osim", 2},
      {"opensim-org/opensim-core/OpenSim/Simulation/Test/"
       "testSimulationUtilities_leg6dof9musc_20303.osim",
       1},
      {"opensim-org/opensim-models/Pipelines/Hamner/outputReference/subject02_registered.osim", 0},
      {"opensim-org/opensim-models/Models/BouncingBlock/bouncing_block.osim", 2}};
  for (const auto& [file, constraints] : models) {
    opensim::OpenSimParser parser;
    auto system = parser.Parse(kData + "/" + file);
    EXPECT_EQ(static_cast<int>(system->constraints().size()) - system->FirstExtraConstraint(),
              constraints)
        << file;
    engine::State state = engine::MakeDefaultState(*system);
    EXPECT_LT(WorstResidual(*system, state), 1e-12) << file;
    for (int c = 0; c < system->num_coordinates(); ++c) state.u[c] = std::sin(c + 1.0);
    engine::PlaceBodies(*system, state);
    engine::ProjectState(*system, state);
    engine::IntegratorSettings settings;
    settings.accuracy = 1e-6;
    auto integrator = engine::MakeIntegrator("rk45", *system, settings);
    double worst = 0.0;
    for (int k = 1; k <= 10; ++k) {
      integrator->StepTo(state, 0.05 * k);
      worst = std::max(worst, WorstResidual(*system, state));
    }
    // The projection after every step holds positions to min(1e-3 accuracy, 1e-10).
    EXPECT_LT(worst, 1e-8) << file;
    std::cout << file << ": " << constraints << " model constraints, residual " << worst
              << " over 0.5 s, " << integrator->stats().steps << " steps ("
              << integrator->stats().rejected << " rejected)\n";
  }
}

TEST(ConstraintsTest, AssemblyKeepsLockedCoordinatesAndMovesFreeOnesLeast) {
  opensim::OpenSimParser parser;
  auto system = parser.Parse(kData + "/sinew/reach.osim");
  engine::State state = engine::MakeDefaultState(*system);
  const int q1 = system->FindCoordinate("q1"), q2 = system->FindCoordinate("q2"),
            q3 = system->FindCoordinate("q3");
  EXPECT_EQ(state.q[q1], 0.3);  // locked: kept exactly
  const std::shared_ptr<const engine::Constraint> reach =
      parser.GetReport().GetConstraint("reach")->constraint;
  VecX phi(1);
  reach->CalcPositionError(*system, state, phi);
  EXPECT_LT(std::abs(phi[0]), 1e-12);
  EXPECT_LT(WorstResidual(*system, state), 1e-12);
  // Least squares with equal weights (OpenSim's CoordinateReference weight 1): the move from
  // the defaults (0.2, -0.1) is parallel to the gradient of the distance in (q2, q3), here by
  // central differences of the tip's distance to the point.
  auto distance = [&](double a2, double a3) {
    engine::State s = state;
    s.q[q2] = a2;
    s.q[q3] = a3;
    engine::PlaceBodies(*system, s);
    return (s.bodies[system->FindBody("link3")].p_GB - Vec3(0.9, -0.6, 0)).norm();
  };
  const double h = 1e-6;
  const Eigen::Vector2d gradient(
      (distance(state.q[q2] + h, state.q[q3]) - distance(state.q[q2] - h, state.q[q3])) / (2 * h),
      (distance(state.q[q2], state.q[q3] + h) - distance(state.q[q2], state.q[q3] - h)) / (2 * h));
  const Eigen::Vector2d move(state.q[q2] - 0.2, state.q[q3] + 0.1);
  EXPECT_GT(move.norm(), 0.05);  // the defaults were 0.089 m off
  const double sine =
      (move.x() * gradient.y() - move.y() * gradient.x()) / (move.norm() * gradient.norm());
  EXPECT_LT(std::abs(sine), 1e-8);  // finite-difference truncation ~h^2
  std::cout << "reach.osim assembled: q2 " << state.q[q2] << ", q3 " << state.q[q3]
            << ", |sin(move, gradient)| " << std::abs(sine) << "\n";
}

TEST(ConstraintsTest, AssemblyMovesTheCoupledCoordinateNotItsDriver) {
  // springs.osim: follower_x = 0.5 spline(arm_angle), defaults arm_angle 0.8, follower_x 0.
  // OpenSim gives a coupler's dependent coordinate no goal: the driver keeps its default.
  opensim::OpenSimParser parser;
  auto system = parser.Parse(kData + "/sinew/springs.osim");
  engine::State state = engine::MakeDefaultState(*system);
  EXPECT_EQ(engine::GetCoordinateValue(*system, state, "arm_angle"), 0.8);
  EXPECT_LT(WorstResidual(*system, state), 1e-12);
  EXPECT_NE(engine::GetCoordinateValue(*system, state, "follower_x"), 0.0);
}

TEST(ConstraintsTest, UnreachableConstraintIsNamedInTheError) {
  opensim::OpenSimParser parser;
  std::string text;
  {
    std::ifstream in(kData + "/sinew/reach.osim");
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const std::string from = "<constant_distance>0.75<", to = "<constant_distance>4<";
  text.replace(text.find(from), from.size(), to);
  const std::string file = ::testing::TempDir() + "/unreachable.osim";
  std::ofstream(file) << text;
  auto system = parser.Parse(file);
  try {
    engine::MakeDefaultState(*system);
    FAIL() << "assembled an unreachable constraint";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("cannot assemble"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("'reach'"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace sinew

// The tree elimination's three kinds of node block: articulated pivots (parameterized joints, the
// joint rows eliminated as in the articulated-body algorithm), direct pivots (direct joints, by
// the range-space method) and the generic LU (a massless body's block, and every block with
// KktSolver::Method::kTreeGenericNodes) solve the same system.
#include <gtest/gtest.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/dynamics.h>
#include <sinew/engine/system.h>
#include <sinew/functions/linear_function.h>

#include <cmath>
#include <memory>
#include <string>

#include "engine/chain_model.h"
#include "engine/test_models.h"
#include "engine/unit_load_responses.h"

namespace sinew::engine {
namespace {

using testing::Coord;
using testing::MakeBody;

// Every joint type on one tree: parameterized Free, Ball (one angle locked), Universal,
// rolling (a coupled rotation and translation), slider (prescribed) and pins, one of them
// reversed (its child is ground); direct Pin, Ball, Universal and Weld; a massless cross
// between two pins; and a coupler between the slider and a pin of another branch.
std::unique_ptr<System> MakeEveryJointTree() {
  auto system = std::make_unique<System>(Vec3(0, -9.81, 0));
  int n = 0;
  auto body = [&](double mass) {
    const double k = 1.0 + 0.1 * n++;
    return system->AddBody(MakeBody("b" + std::to_string(n), mass, Vec3(0.02 * k, -0.1, 0.01),
                                    mass * 1e-2 * Vec3(k, 1.3, 0.7 * k).asDiagonal()));
  };
  auto at = [](double x, double y, double z) { return Transform::Translation(Vec3(x, y, z)); };
  const auto kP = JointForm::kParameterized;
  const int pelvis = body(10.0);
  system->AddJoint("free", 0, at(0, 1, 0), pelvis, Transform::Identity(), kP,
                   std::make_shared<testing::FreeModel>(),
                   {Coord("fx", 0.1, 0.3), Coord("fy", -0.2, 0.1), Coord("fz", 0.3, -0.2),
                    Coord("tx", 0.0, 0.1), Coord("ty", 1.0, 0.2), Coord("tz", 0.1, -0.1)});
  CoordinateDesc locked = Coord("bz", 0.2);
  locked.motion = CoordinateMotion::kLocked;
  const int thigh = body(5.0);
  system->AddJoint("ball", pelvis, at(0.1, -0.1, 0), thigh, at(0, 0.2, 0), kP,
                   std::make_shared<testing::BallModel>(),
                   {Coord("bx", 0.3, 0.5), Coord("by", -0.1, 0.4), locked});
  const int shank = body(3.0);
  system->AddJoint("universal", thigh, at(0, -0.4, 0), shank, at(0, 0.2, 0), kP,
                   std::make_shared<testing::UniversalModel>(),
                   {Coord("ux", 0.4, -0.3), Coord("uy", 0.2, 0.6)});
  const int foot = body(1.0);
  system->AddJoint("rolling", shank, at(0, -0.4, 0), foot, Transform::Identity(), kP,
                   std::make_shared<testing::RollingModel>(0.05), {Coord("roll", 0.3, 1.0)});
  CoordinateDesc prescribed = Coord("slide", 0.05, 0.2);
  prescribed.motion = CoordinateMotion::kPrescribed;
  prescribed.prescribed = std::make_shared<functions::LinearFunction>(0.2, 0.05);
  const int slider = body(0.5);
  system->AddJoint("slider", foot, at(0.1, 0, 0), slider, Transform::Identity(), kP,
                   std::make_shared<testing::SliderModel>(), {prescribed});
  // The other branch, on direct joints, with a massless cross between two parameterized pins.
  const int trunk = body(8.0);
  system->AddJoint("pin", pelvis, at(0, 0.1, 0), trunk, at(0, -0.2, 0), JointForm::kPin, nullptr,
                   {Coord("pz", 0.2, -0.4)});
  const int head = body(2.0);
  system->AddJoint("dball", trunk, at(0, 0.3, 0), head, at(0, -0.1, 0), JointForm::kBall, nullptr,
                   {Coord("hx", 0.1, 0.2), Coord("hy", 0.2), Coord("hz", -0.1, 0.3)});
  const int arm = body(1.5);
  system->AddJoint("duniversal", trunk, at(0.2, 0.2, 0), arm, at(0, 0.1, 0), JointForm::kUniversal,
                   nullptr, {Coord("ax", 0.5, 0.1), Coord("ay", 0.1)});
  const int hand = body(0.4);
  system->AddJoint("weld", arm, at(0, -0.3, 0), hand, Transform::Identity(), JointForm::kWeld,
                   nullptr, {});
  const int cross = system->AddBody(MakeBody("cross", 0.0, Vec3::Zero(), Mat3::Zero()));
  system->AddJoint("cx", trunk, at(-0.2, 0.2, 0), cross, Transform::Identity(), kP,
                   std::make_shared<testing::RevoluteModel>(Vec3::UnitX()),
                   {Coord("cx", 0.3, -0.2)});
  const int other_arm = body(1.5);
  system->AddJoint("cy", cross, Transform::Identity(), other_arm, at(0, 0.1, 0), kP,
                   std::make_shared<testing::RevoluteModel>(Vec3::UnitY()),
                   {Coord("cy", -0.2, 0.3)});
  // A reversed joint: the tail hangs from ground through a pin whose parent is the tail.
  const int tail = body(0.7);
  system->AddJoint("reversed", tail, at(0, 0.2, 0), 0, at(1, 2, 0), kP,
                   std::make_shared<testing::RevoluteModel>(Vec3::UnitZ()),
                   {Coord("rz", 0.4, 0.5)});
  // roll = 0.5 cy: a coupler across the two branches (Schur complement).
  system->AddConstraint(std::make_shared<testing::LeverConstraint>(
      system->FindCoordinate("roll"), system->FindCoordinate("cy"), 0.5));
  system->Finalize();
  return system;
}

TEST(TreeSolverTest, ClosedFormPivotsEqualTheGenericLu) {
  const auto system = MakeEveryJointTree();
  ASSERT_TRUE(system->IsReversed(system->FindJoint("reversed")));
  State state = MakeDefaultState(*system);
  for (int c = 0; c < system->num_coordinates(); ++c) state.u[c] += 0.1 * std::cos(c + 1.0);
  PlaceBodies(*system, state);
  Data articulated(*system), generic(*system, KktSolver::Method::kTreeGenericNodes),
      dense(*system, KktSolver::Method::kDense);
  ASSERT_EQ(articulated.kkt.num_extra_equations(), 1);
  const Accelerations a = CalcAccelerations(*system, state, nullptr, articulated);
  const Accelerations b = CalcAccelerations(*system, state, nullptr, generic);
  const Accelerations d = CalcAccelerations(*system, state, nullptr, dense);
  // Free, ball, universal, rolling, slider, the two pins about the cross, the reversed pin.
  EXPECT_EQ(articulated.kkt.num_articulated_nodes(), 8);
  // Direct pin, ball, universal and weld.
  EXPECT_EQ(articulated.kkt.num_direct_nodes(), 4);
  EXPECT_EQ(generic.kkt.num_articulated_nodes(), 0);
  EXPECT_EQ(generic.kkt.num_direct_nodes(), 0);
  EXPECT_LT((a.vdot - b.vdot).lpNorm<Eigen::Infinity>(), 1e-12 * b.vdot.lpNorm<Eigen::Infinity>());
  EXPECT_LT((a.lambda - b.lambda).lpNorm<Eigen::Infinity>(),
            1e-12 * b.lambda.lpNorm<Eigen::Infinity>());
  EXPECT_LT((a.vdot - d.vdot).lpNorm<Eigen::Infinity>(), 1e-10 * d.vdot.lpNorm<Eigen::Infinity>());
  EXPECT_LT((a.lambda - d.lambda).lpNorm<Eigen::Infinity>(),
            1e-10 * d.lambda.lpNorm<Eigen::Infinity>());
}

TEST(TreeSolverTest, ReusedFactorizationGivesTheSameAccelerations) {
  const auto system = MakeEveryJointTree();
  State state = MakeDefaultState(*system);
  PlaceBodies(*system, state);
  Data data(*system);
  const VecX first = CalcAccelerations(*system, state, nullptr, data).vdot;
  ASSERT_TRUE(data.kkt.IsFactorizedAt(state));
  const long factorizations = data.kkt.num_factorizations();
  state.u *= 2.0;  // velocities do not enter the matrix
  const VecX reused = CalcAccelerationsReusingFactorization(*system, state, nullptr, data).vdot;
  EXPECT_EQ(data.kkt.num_factorizations(), factorizations);
  Data fresh(*system);
  EXPECT_EQ(reused, CalcAccelerations(*system, state, nullptr, fresh).vdot);  // bit for bit
  EXPECT_NE(reused, first);
  state.q[system->FindCoordinate("cx")] += 1e-15;  // positions do
  EXPECT_FALSE(data.kkt.IsFactorizedAt(state));
}

TEST(TreeSolverTest, UnitLoadResponsesOnEveryJointTreeEqualFullSolves) {
  // Every node kind, the massless cross, the reversed tail and the coupler across the branches
  // (one Schur row): every body loaded, every body read (1e-12 relative, rounding).
  const auto system = MakeEveryJointTree();
  State state = MakeDefaultState(*system);
  PlaceBodies(*system, state);
  std::vector<int> bodies;
  for (int b = system->num_bodies() - 1; b > 0; --b) bodies.push_back(b);
  for (const auto method : {KktSolver::Method::kTree, KktSolver::Method::kTreeGenericNodes}) {
    KktSolver kkt(*system, method);
    kkt.Factorize(state);
    ASSERT_EQ(kkt.num_extra_equations(), 1);
    for (int source : bodies) {
      EXPECT_LT(testing::UnitLoadResponseError(kkt, source, bodies), 1e-12)
          << static_cast<int>(method) << " " << system->bodies()[source].name;
    }
  }
}

}  // namespace
}  // namespace sinew::engine

namespace sinew::engine::testing {
namespace {

// Rods (ConstantDistanceConstraint) between the tips of links half a direct-pin chain apart:
// rows outside the tree, solved by the Schur complement beside the tree elimination, give the
// dense solve's accelerations and multipliers (bench_engine_chain's BM_ChainWithRodsAccelerations).
TEST(TreeSolverTest, RodsOnADirectChainEqualTheDenseSolve) {
  const System system = MakeChain(20, JointForm::kPin, 0, 3);
  State state = MakeDefaultState(system);
  for (int c = 0; c < system.num_coordinates(); ++c) state.u[c] += 0.5 * std::cos(c + 1.0);
  PlaceBodies(system, state);
  Data tree(system), dense(system, KktSolver::Method::kDense);
  const Accelerations a = CalcAccelerations(system, state, nullptr, tree);
  const Accelerations d = CalcAccelerations(system, state, nullptr, dense);
  EXPECT_EQ(tree.kkt.num_extra_equations(), 3);
  EXPECT_EQ(tree.kkt.num_direct_nodes(), 20);
  EXPECT_LT((a.vdot - d.vdot).lpNorm<Eigen::Infinity>(), 1e-10 * d.vdot.lpNorm<Eigen::Infinity>());
  EXPECT_LT((a.lambda - d.lambda).lpNorm<Eigen::Infinity>(),
            1e-10 * d.lambda.lpNorm<Eigen::Infinity>());
}

// The twist responses to unit loads that NSC contact needs (only the tree paths between the
// bodies and ground visited, plus the Schur complement's correction for constraints outside
// the tree) equal the corresponding entries of full solves, to rounding (1e-12 relative: both
// are the same exact elimination, summed in another order).
TEST(TreeSolverTest, UnitLoadResponsesEqualFullSolves) {
  const System system = MakeChain(12, JointForm::kParameterized);
  KktSolver kkt(system);
  kkt.Factorize(MakeDefaultState(system));
  ASSERT_EQ(kkt.num_extra_equations(), 0);
  EXPECT_LT(UnitLoadResponseError(kkt, 6, {1, 6, 12, 3}), 1e-12);
}

TEST(TreeSolverTest, UnitLoadResponsesWithCouplersEqualFullSolves) {
  // Three levers q[i] = 0.5 q[i + 10] (i = 0, 3, 6): Schur complement rows that couple bodies
  // on separate paths; sources on and off the coupled joints, targets on the source's path,
  // beyond it, repeated and the source itself.
  const System system = MakeChain(20, JointForm::kParameterized, 3);
  State state = MakeDefaultState(system);
  for (int c = 0; c < system.num_coordinates(); ++c) state.q[c] = 0.3 * std::sin(c + 1.0);
  PlaceBodies(system, state);
  for (const auto method : {KktSolver::Method::kTree, KktSolver::Method::kTreeGenericNodes}) {
    KktSolver kkt(system, method);
    kkt.Factorize(state);
    ASSERT_EQ(kkt.num_extra_equations(), 3);
    const std::vector<std::pair<int, std::vector<int>>> cases = {
        {1, {1}}, {4, {1, 4, 11, 20}}, {11, {20, 11, 2, 2, 17}}, {20, {7, 14, 1, 20}}};
    for (const auto& [source, targets] : cases) {
      EXPECT_LT(UnitLoadResponseError(kkt, source, targets), 1e-12)
          << static_cast<int>(method) << " " << source;
    }
  }
  // The dense method keeps no tree: refused.
  KktSolver dense(system, KktSolver::Method::kDense);
  dense.Factorize(state);
  MatX responses(6, 6);
  EXPECT_FALSE(dense.SolveUnitLoadResponses(4, {4}, responses));
}

}  // namespace
}  // namespace sinew::engine::testing

// The fixed-step schemes' position update along the joint tree (ApplyTreeDisplacement): after
// it every tree joint holds to rounding, whatever the displacement, and it is a first-order
// update like the bodies' rigid displacement (ApplyPositionDisplacement): the two differ by
// O(h^2), checked by halving h.
#include <gtest/gtest.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/kkt.h>
#include <sinew/engine/projection.h>
#include <sinew/engine/tree_displacement.h>

#include <memory>
#include <vector>

#include "engine/test_models.h"

namespace sinew::engine {
namespace {

// Every joint form, one of them used reversed (its child is nearer ground), every body moving:
// ground -pin- A -ball- B -universal- C -weld- D -free (parameterized)- E, and F hangs from A
// through a parameterized universal whose parent is F.
System MakeEveryForm() {
  System system(Vec3(0, -9.81, 0));
  const auto body = [&](const std::string& name, double m) {
    return system.AddBody(testing::MakeBody(name, m, Vec3(0.02, -0.1, 0.01),
                                            Vec3(0.02, 0.01, 0.03).asDiagonal()));
  };
  const int a = body("A", 1.0), b = body("B", 0.8), c = body("C", 0.6), d = body("D", 0.5),
            e = body("E", 0.4), f = body("F", 0.3);
  const Transform below(Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()).toRotationMatrix(),
                        Vec3(0.01, -0.2, 0.03));
  const Transform M_offset(Eigen::AngleAxisd(-0.2, Vec3(0, 1, 1).normalized()).toRotationMatrix(),
                           Vec3(0.0, 0.05, -0.02));
  using testing::Coord;
  system.AddJoint("pin", 0, below, a, M_offset, JointForm::kPin, nullptr, {Coord("q0", 0.4, 1.5)});
  system.AddJoint("ball", a, below, b, M_offset, JointForm::kBall, nullptr,
                  {Coord("b0", 0.2, 2.0), Coord("b1", -0.3, -1.0), Coord("b2", 0.5, 3.0)});
  system.AddJoint("universal", b, below, c, M_offset, JointForm::kUniversal, nullptr,
                  {Coord("u0", 0.3, -2.5), Coord("u1", 0.6, 1.7)});
  system.AddJoint("weld", c, below, d, M_offset, JointForm::kWeld, nullptr, {});
  system.AddJoint("free", d, below, e, M_offset, JointForm::kParameterized,
                  std::make_shared<testing::FreeModel>(),
                  {Coord("rx", 0.1, 1.0), Coord("ry", 0.2, -2.0), Coord("rz", -0.3, 0.5),
                   Coord("tx", 0.05, 0.3), Coord("ty", -0.02, 0.2), Coord("tz", 0.01, -0.4)});
  system.AddJoint("reversed", f, below, a, M_offset, JointForm::kParameterized,
                  std::make_shared<testing::UniversalModel>(),
                  {Coord("v0", 0.4, 1.2), Coord("v1", -0.5, 0.8)});
  system.Finalize();
  return system;
}

// The state after moving by h times its velocities, along the tree or rigidly.
State Displaced(const System& system, const State& start, double h, bool along_tree) {
  KktSolver kkt(system);
  const VecX dx = h * GatherVelocities(system, kkt, start);
  State moved = start;
  if (along_tree) {
    ApplyTreeDisplacement(system, kkt, dx, moved);
  } else {
    ApplyPositionDisplacement(system, kkt, dx, moved);
  }
  return moved;
}

double PoseDifference(const State& a, const State& b) {
  double largest = (a.q - b.q).lpNorm<Eigen::Infinity>();
  for (size_t i = 1; i < a.bodies.size(); ++i) {
    largest = std::max(largest, (a.bodies[i].p_GB - b.bodies[i].p_GB).norm());
    largest = std::max(largest, a.bodies[i].quat_GB.angularDistance(b.bodies[i].quat_GB));
  }
  return largest;
}

TEST(TreeDisplacementTest, EveryTreeJointHoldsAfterAnyDisplacement) {
  const System system = MakeEveryForm();
  ASSERT_TRUE(system.IsReversed(5));
  const State start = MakeDefaultState(system);
  ASSERT_LE(CalcPositionErrors(system, start).lpNorm<Eigen::Infinity>(), 1e-14);
  for (double h : {1e-3, 1e-2, 0.1, 1.0}) {
    SCOPED_TRACE(h);
    const State tree = Displaced(system, start, h, true);
    // Rounding of a few composed rotations: a few eps of the 0.2 m lever arms and 1 rad angles.
    EXPECT_LE(CalcPositionErrors(system, tree).lpNorm<Eigen::Infinity>(), 1e-14);
    // The rigid displacement leaves the joints by O(h^2) (here about 10 h^2).
    const State rigid = Displaced(system, start, h, false);
    EXPECT_GT(CalcPositionErrors(system, rigid).lpNorm<Eigen::Infinity>(), h * h);
  }
}

TEST(TreeDisplacementTest, DiffersFromTheRigidDisplacementAtSecondOrder) {
  const System system = MakeEveryForm();
  const State start = MakeDefaultState(system);
  // Both are first-order updates by the same velocities: their difference falls by 4 when h
  // halves, and each moved from the start by O(h).
  double previous = 0.0;
  for (double h : {4e-3, 2e-3, 1e-3, 5e-4}) {
    const State tree = Displaced(system, start, h, true);
    const double difference = PoseDifference(tree, Displaced(system, start, h, false));
    EXPECT_GT(PoseDifference(tree, start), 100 * difference);
    if (previous > 0.0) {
      EXPECT_NEAR(previous / difference, 4.0, 0.1) << h;
    }
    previous = difference;
  }
}

}  // namespace
}  // namespace sinew::engine

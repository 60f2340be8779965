// The body-to-body constraints (engine::FrameConstraint as OpenSim's PointConstraint and
// WeldConstraint, PointOnLineConstraint, ConstantDistanceConstraint): with both bodies moving
// and turning, J v and the acceleration right-hand side b are the first and second time
// derivatives of phi along a motion of constant twists (central differences), and bad
// parameters are refused by name.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/engine/frame_constraint.h>
#include <sinew/engine/pose.h>
#include <sinew/engine/state.h>
#include <sinew/engine/system.h>
#include <sinew/forces/constant_distance_constraint.h>
#include <sinew/forces/point_on_line_constraint.h>

#include <memory>
#include <string>
#include <vector>

namespace sinew::forces {
namespace {

// Ground and two bodies in general poses with general twists.
engine::State MovingBodies() {
  engine::State state;
  state.bodies.resize(3);
  state.bodies[1].p_GB = Vec3(0.3, -0.2, 0.5);
  state.bodies[1].quat_GB = Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, -1).normalized()));
  state.bodies[1].w_GB = Vec3(1.1, -0.4, 0.9);
  state.bodies[1].v_GB = Vec3(-0.3, 0.8, 0.2);
  state.bodies[2].p_GB = Vec3(-0.4, 0.6, 0.1);
  state.bodies[2].quat_GB = Quat(Eigen::AngleAxisd(-1.2, Vec3(0.5, -1, 2).normalized()));
  state.bodies[2].w_GB = Vec3(-0.7, 1.3, 0.5);
  state.bodies[2].v_GB = Vec3(0.6, 0.1, -0.9);
  return state;
}

// The state moved by time `t` along constant twists: p(t) = p + v t, R(t) = exp(w t) R.
engine::State Advance(const engine::State& state, double t) {
  engine::State moved = state;
  for (engine::BodyState& b : moved.bodies) {
    b.p_GB += b.v_GB * t;
    b.quat_GB = (engine::QuatFromRotationVector(b.w_GB * t) * b.quat_GB).normalized();
  }
  return moved;
}

void ExpectDerivativesOfPhi(const engine::Constraint& constraint, const std::string& what) {
  const engine::System system;
  const engine::State state = MovingBodies();
  const int n = constraint.NumEquations();
  VecX v(12);
  for (int i = 0; i < 2; ++i) {
    const engine::BodyState& b = state.bodies[constraint.Bodies()[i]];
    v.segment<3>(6 * i) = b.w_GB;
    v.segment<3>(6 * i + 3) = b.v_GB;
  }
  MatX J(n, 12);
  VecX b(n), phi0(n), plus(n), minus(n);
  constraint.CalcJacobian(system, state, J);
  constraint.CalcAccelerationRhs(system, state, b);
  constraint.CalcPositionError(system, state, phi0);
  const double h = 1e-4;
  constraint.CalcPositionError(system, Advance(state, h), plus);
  constraint.CalcPositionError(system, Advance(state, -h), minus);
  // Truncation h^2 |phi'''| ~ 1e-8 and rounding 1e-16 / h^2 ~ 1e-8 for the second difference.
  EXPECT_LT(((plus - minus) / (2 * h) - J * v).lpNorm<Eigen::Infinity>(), 1e-7) << what;
  // Constant twists: vdot = 0, so phi'' = Jdot v = -b.
  EXPECT_LT(((plus - 2 * phi0 + minus) / (h * h) + b).lpNorm<Eigen::Infinity>(), 1e-5) << what;
}

TEST(BodyConstraintsTest, JacobianAndAccelerationTermAreDerivativesOfPhi) {
  const Transform X_1F(Eigen::AngleAxisd(0.4, Vec3::UnitY()).toRotationMatrix(), Vec3(0.1, 0, 0.2));
  const Transform X_2M(Eigen::AngleAxisd(-0.3, Vec3::UnitX()).toRotationMatrix(),
                       Vec3(0, -0.3, 0.1));
  for (auto kind : {engine::FrameConstraintKind::kPoint, engine::FrameConstraintKind::kWeld}) {
    ExpectDerivativesOfPhi(engine::FrameConstraint("frames", 1, X_1F, 2, X_2M, kind),
                           kind == engine::FrameConstraintKind::kWeld ? "weld" : "point");
  }
  ExpectDerivativesOfPhi(PointOnLineConstraint("line", 1, Vec3(0.3, 1, -0.5), Vec3(0.2, 0.1, 0), 2,
                                               Vec3(0, 0.2, -0.1)),
                         "point on line");
  ExpectDerivativesOfPhi(
      ConstantDistanceConstraint("rod", 1, Vec3(0.1, 0.2, 0), 2, Vec3(-0.2, 0, 0.3), 0.8), "rod");
}

TEST(BodyConstraintsTest, BadParametersAreRefusedByName) {
  const auto expect_error = [](auto make, const std::string& text) {
    try {
      make();
      ADD_FAILURE() << "accepted: " << text;
    } catch (const Error& error) {
      EXPECT_NE(std::string(error.what()).find(text), std::string::npos) << error.what();
    }
  };
  expect_error(
      [] { PointOnLineConstraint("rail", 0, Vec3::Zero(), Vec3::Zero(), 1, Vec3::Zero()); },
      "rail: line_direction_vec is zero");
  expect_error([] { ConstantDistanceConstraint("rod", 0, Vec3::Zero(), 1, Vec3::Zero(), 0.0); },
               "rod: constant_distance must be a finite length > 0");
  expect_error([] { ConstantDistanceConstraint("rod", 1, Vec3::Zero(), 1, Vec3::UnitX(), 1.0); },
               "rod: body_1 and body_2 are the same body");
}

}  // namespace
}  // namespace sinew::forces

// The articulated elimination of a direct joint's block (DirectPivot) against a dense LU of the
// whole block, for every direct form's number of joint rows (ball 3, universal 4, pin 5, weld
// 6), a point mass on a weld (no rotational inertia, which the weld takes away), and its refusal
// of a free rotation without inertia.
#include <gtest/gtest.h>
#include <sinew/engine/direct_pivot.h>
#include <sinew/math/rotation.h>

#include <Eigen/LU>

#include "engine/test_models.h"

namespace sinew::engine {
namespace {

using Mat6 = Eigen::Matrix<double, 6, 6>;
using Block = MatX;  // a node block (the pivot reads a view of it)

using testing::SpatialInertia;

// The rows of a joint holding the body's point r_B (from its origin) at the parent's point d,
// with `free_rotations` of the body's rotations left free about axes turned by R, in a
// FrameConstraint's layout: the point rows, then the rotation rows (the other axes' components
// of the relative angular velocity).
struct JointRows {
  MatX J_B, J_P;  // m x 6 on the body's and the parent's twist
};
JointRows MakeJointRows(int free_rotations, const Mat3& R, const Vec3& r_B, const Vec3& d) {
  const int m = 6 - free_rotations;
  JointRows rows{MatX::Zero(m, 6), MatX::Zero(m, 6)};
  // Point velocity v + w x r = v - [r]x w, on each side.
  rows.J_B.block<3, 3>(0, 0) = -Skew(r_B);
  rows.J_B.block<3, 3>(0, 3) = Mat3::Identity();
  rows.J_P.block<3, 3>(0, 0) = Skew(d);
  rows.J_P.block<3, 3>(0, 3) = -Mat3::Identity();
  for (int i = 0; i < 3 - free_rotations; ++i) {
    const Vec3 axis = R.col(i);
    rows.J_B.block<1, 3>(3 + i, 0) = axis.transpose();
    rows.J_P.block<1, 3>(3 + i, 0) = -axis.transpose();
  }
  return rows;
}

Block MakeBlock(const Mat6& M, const MatX& J_B) {
  const int m = static_cast<int>(J_B.rows());
  Block K = Block::Zero(6 + m, 6 + m);
  K.topLeftCorner<6, 6>() = M;
  K.bottomLeftCorner(m, 6) = J_B;
  K.topRightCorner(6, m) = J_B.transpose();
  return K;
}

TEST(DirectPivotTest, SolvesAndCouplingEqualADenseLuForEveryDirectForm) {
  const Mat6 M = SpatialInertia(3.0, Vec3(0.02, -0.15, 0.01), Vec3(0.04, 0.01, 0.035).asDiagonal());
  const Mat3 R = RotationFromBodyFixedXYZ(Vec3(0.3, -0.7, 1.1));
  for (int free_rotations = 0; free_rotations <= 3; ++free_rotations) {
    const int m = 6 - free_rotations;
    SCOPED_TRACE(::testing::Message() << m << " joint rows");
    const JointRows rows =
        MakeJointRows(free_rotations, R, Vec3(0.1, -0.2, 0.03), Vec3(-0.05, 0.4, 0.1));
    const Block K = MakeBlock(M, rows.J_B);
    DirectPivot pivot;
    ASSERT_TRUE(pivot.Factorize(K));
    const MatX dense = K;
    const Eigen::FullPivLU<MatX> lu(dense);
    // These blocks' condition numbers are below 1e4: 1e-11 relative leaves a margin of 1e3 over
    // the rounding of either method.
    MatX r(6 + m, 2);
    for (int i = 0; i < r.rows(); ++i) {
      r(i, 0) = std::sin(1.0 + i);
      r(i, 1) = std::cos(2.0 * i);
    }
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 24, 6> x = r;
    pivot.SolveInPlace(x);
    const MatX x_dense = lu.solve(r);
    EXPECT_LT((MatX(x) - x_dense).lpNorm<Eigen::Infinity>(),
              1e-11 * x_dense.lpNorm<Eigen::Infinity>());
    // The coupling C = [0; J_P]: W = K^-1 C and the parent's update C^T W.
    MatX C = MatX::Zero(6 + m, 6);
    C.bottomRows(m) = rows.J_P;
    Eigen::Matrix<double, Eigen::Dynamic, 6, 0, 24, 6> W(6 + m, 6);
    Mat6 CtW;
    pivot.SolveCoupling(rows.J_P, W, CtW);
    const MatX W_dense = lu.solve(C);
    const MatX CtW_dense = C.transpose() * W_dense;
    EXPECT_LT((MatX(W) - W_dense).lpNorm<Eigen::Infinity>(),
              1e-11 * W_dense.lpNorm<Eigen::Infinity>());
    EXPECT_LT((MatX(CtW) - CtW_dense).lpNorm<Eigen::Infinity>(),
              1e-11 * CtW_dense.lpNorm<Eigen::Infinity>());
    // The parent gains the body's inertia as the joint transmits it: symmetric, and all of it
    // for a weld (-C^T W = J_P^T J_B^-T M J_B^-1 J_P, the body rigidly on the parent).
    EXPECT_LT((CtW - CtW.transpose()).lpNorm<Eigen::Infinity>(),
              1e-12 * CtW.lpNorm<Eigen::Infinity>());
    if (m == 6) {
      const Mat6 A = rows.J_B.inverse() * rows.J_P;
      const Mat6 rigid = A.transpose() * M * A;
      EXPECT_LT((-CtW - rigid).lpNorm<Eigen::Infinity>(), 1e-11 * rigid.lpNorm<Eigen::Infinity>());
    }
  }
}

TEST(DirectPivotTest, PointMassOnAWeldAndRefusalOfAFreeRotationWithoutInertia) {
  // A point mass on a weld: M_A has no rotational inertia, but the weld fixes every direction,
  // so the block is regular and the elimination (which never inverts M_A) exact.
  const Mat6 point = SpatialInertia(0.5, Vec3::Zero(), Mat3::Zero());
  const JointRows weld = MakeJointRows(0, Mat3::Identity(), Vec3(0.1, 0, 0), Vec3::Zero());
  const Block K = MakeBlock(point, weld.J_B);
  DirectPivot pivot;
  ASSERT_TRUE(pivot.Factorize(K));
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 24, 6> x = MatX::Ones(12, 1);
  pivot.SolveInPlace(x);
  const MatX x_dense = MatX(K).fullPivLu().solve(MatX::Ones(12, 1));
  EXPECT_LT((MatX(x) - x_dense).lpNorm<Eigen::Infinity>(),
            1e-12 * x_dense.lpNorm<Eigen::Infinity>());
  // The same point mass on a ball joint: its rotations are free and have no inertia, the block
  // is singular, and the generic LU must report it.
  const JointRows ball = MakeJointRows(3, Mat3::Identity(), Vec3(0.1, 0, 0), Vec3::Zero());
  EXPECT_FALSE(pivot.Factorize(MakeBlock(point, ball.J_B)));
}

}  // namespace
}  // namespace sinew::engine

// The closed-form coupling of an articulated pivot (W = K^-1 C and the parent's update C^T W from
// the small system on the joint speeds) equals six solves of the whole block, and a dense LU of
// it, for every number of joint speeds (0 to 6: weld-like to free) with and without coordinate
// rows (locks, prescribed motion, a row mixing speeds), and for a point mass whose joint takes
// away its rotations.
#include <gtest/gtest.h>
#include <sinew/engine/articulated_pivot.h>
#include <sinew/math/rotation.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "engine/test_models.h"

namespace sinew::engine {
namespace {

using Mat6 = Eigen::Matrix<double, 6, 6>;
using Block = MatX;  // a node block (the pivot reads a view of it)

using testing::SpatialInertia;

struct PivotCase {
  Block K;
  MatX C;  // n x 6
  // Scale of the parent's update: the body's inertia rigidly attached to the parent,
  // |A^T M A| with the shift A = J_B^-1 J_P (the update is zero when the joint leaves every
  // direction with inertia free, so it cannot be its own scale).
  double scale = 0.0;
};

// A block with the articulated layout: body inertia M, joint rows J_B (block lower triangular,
// as a parameterized joint's) with speeds' columns J_u = -J_B S, the parent's block J_P in C,
// and coordinate rows N.
PivotCase MakeCase(const Mat6& M, const Mat6X& S, const MatX& N, int seed) {
  const int nu = static_cast<int>(S.cols()), nc = static_cast<int>(N.rows());
  const double s = 0.3 * seed;
  const Mat3 Rt = RotationFromBodyFixedXYZ(Vec3(0.3 + s, -0.7, 1.1 - s)).transpose();
  const Vec3 r_BM(0.1, -0.2 + 0.05 * s, 0.03), d(-0.05, 0.4, 0.1 * s);
  Mat6 J_B = Mat6::Zero(), J_P = Mat6::Zero();
  J_B << Rt, Mat3::Zero(), -Rt * Skew(r_BM), Rt;
  J_P << -Rt, Mat3::Zero(), Rt * Skew(d), -Rt;
  const int n = 12 + nu + nc;
  PivotCase c{Block::Zero(n, n), MatX::Zero(n, 6)};
  c.K.topLeftCorner<6, 6>() = M;
  c.K.block<6, 6>(6 + nu, 0) = J_B;
  c.K.block<6, 6>(0, 6 + nu) = J_B.transpose();
  const MatX J_u = -J_B * S;
  c.K.block(6 + nu, 6, 6, nu) = J_u;
  c.K.block(6, 6 + nu, nu, 6) = J_u.transpose();
  c.K.block(12 + nu, 6, nc, nu) = N;
  c.K.block(6, 12 + nu, nu, nc) = N.transpose();
  c.C.middleRows<6>(6 + nu) = J_P;
  const Mat6 A = J_B.inverse() * J_P;
  c.scale = (A.transpose() * M * A).lpNorm<Eigen::Infinity>();
  return c;
}

// |a - b| relative to `scale`, by default b's.
double RelativeError(const MatX& a, const MatX& b, double scale = 0.0) {
  return (a - b).lpNorm<Eigen::Infinity>() / (scale > 0.0 ? scale : b.lpNorm<Eigen::Infinity>());
}

// Checks SolveCoupling against SolveInPlace on C (1e-12: the same elimination, rounded
// differently) and against a dense LU of K (1e-10: these blocks' condition numbers are below
// 1e4), and that the parent's update is symmetric.
// Returns the parent's update relative to its scale.
double ExpectCouplingExact(const PivotCase& c, int nu) {
  ArticulatedPivot pivot;
  EXPECT_TRUE(pivot.Factorize(c.K, nu));
  const int n = static_cast<int>(c.K.rows());
  MatX W(n, 6);
  Mat6 CtW;
  pivot.SolveCoupling(Mat6(c.C.middleRows<6>(6 + nu)), W, CtW);
  Eigen::Matrix<double, Eigen::Dynamic, 6, 0, 24, 6> solved = c.C;
  pivot.SolveInPlace(solved);
  const MatX W_solved = solved;
  const MatX CtW_solved = c.C.transpose() * W_solved;
  EXPECT_LT(RelativeError(W, W_solved), 1e-12);
  EXPECT_LT(RelativeError(CtW, CtW_solved, c.scale), 1e-12);
  const MatX K = c.K;
  const MatX W_dense = K.fullPivLu().solve(c.C);
  EXPECT_LT(RelativeError(W, W_dense), 1e-10);
  EXPECT_LT(RelativeError(CtW, c.C.transpose() * W_dense, c.scale), 1e-10);
  EXPECT_LT(RelativeError(CtW, CtW.transpose(), c.scale), 1e-12);
  return CtW.lpNorm<Eigen::Infinity>() / c.scale;
}

TEST(ArticulatedPivotTest, ClosedFormCouplingEqualsSolvesForEveryNumberOfSpeeds) {
  const Mat6 M = SpatialInertia(3.0, Vec3(0.02, -0.15, 0.01), Vec3(0.04, 0.01, 0.035).asDiagonal());
  for (int nu = 0; nu <= 6; ++nu) {
    for (int nc = 0; nc <= std::min(nu, 2); ++nc) {
      SCOPED_TRACE(::testing::Message() << nu << " speeds, " << nc << " coordinate rows");
      // Columns of a free joint's motion subspace, taken in turn, with a coupling mixed in.
      Mat6X S = Mat6X::Zero(6, nu);
      for (int k = 0; k < nu; ++k) {
        S(k, k) = 1.0;
        S((k + 3) % 6, k) = 0.1 * (k + 1);
      }
      MatX N = MatX::Zero(nc, nu);
      for (int i = 0; i < nc; ++i) N(i, i) = 1.0;  // a lock or a prescribed speed
      if (nc == 2) N(1, 0) = -0.5;                 // and a row mixing two speeds
      const double update = ExpectCouplingExact(MakeCase(M, S, N, nu + nc), nu);
      // A free joint hands its parent no inertia; any joint that fixes a direction does.
      if (nu == 6 && nc == 0) {
        EXPECT_LT(update, 1e-12);
      } else {
        EXPECT_GT(update, 1e-3);
      }
    }
  }
}

// Every speed locked or prescribed one by one (a locked joint: a hung skeleton's pelvis), N a
// scaled permutation: solved without the small LU. Checked as above and, for right-hand sides
// on every row (twist, speeds, joint rows, coordinate rows), against a dense LU of K.
TEST(ArticulatedPivotTest, EverySpeedLockedSolvesAsTheDenseLu) {
  for (int nu = 1; nu <= 6; ++nu) {
    for (int variant = 0; variant < 2; ++variant) {
      SCOPED_TRACE(::testing::Message() << nu << " speeds, variant " << variant);
      const Mat6 M = SpatialInertia(2.0 + nu, Vec3(0.05, -0.1, 0.02 * nu),
                                    Vec3(0.11, 0.07, 0.05).asDiagonal());
      Mat6X S = Mat6X::Zero(6, nu);
      for (int k = 0; k < nu; ++k) {
        S(k, k) = 1.0;
        S((k + 2) % 6, k) = 0.3 * (k + 1);
      }
      // Identity rows in order, or reversed and scaled (a prescribed speed's row may carry a
      // factor, and the rows need not follow the speeds' order).
      MatX N = MatX::Zero(nu, nu);
      for (int i = 0; i < nu; ++i) {
        if (variant == 0) {
          N(i, i) = 1.0;
        } else {
          N(i, nu - 1 - i) = -0.5 - 0.25 * i;
        }
      }
      const PivotCase c = MakeCase(M, S, N, nu + variant);
      ExpectCouplingExact(c, nu);
      ArticulatedPivot pivot;
      ASSERT_TRUE(pivot.Factorize(c.K, nu));
      const int n = static_cast<int>(c.K.rows());
      Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 24, 1> x(n);
      for (int i = 0; i < n; ++i) x[i] = std::sin(1.7 * i + nu) + 0.2 * variant;
      const VecX rhs = x;
      pivot.SolveInPlace(x);
      const MatX K = c.K;
      const VecX dense = K.fullPivLu().solve(rhs);
      EXPECT_LT(RelativeError(x, dense), 1e-10);
    }
  }
}

TEST(ArticulatedPivotTest, ClosedFormCouplingForAPointMassOnTranslations) {
  // No rotational inertia: the joint (three translations) takes the rotations away.
  const Mat6 M = SpatialInertia(0.5, Vec3::Zero(), Mat3::Zero());
  Mat6X S = Mat6X::Zero(6, 3);
  S.bottomRows<3>().setIdentity();
  // Its parent gains nothing: the point mass translates freely and has no rotational inertia.
  EXPECT_LT(ExpectCouplingExact(MakeCase(M, S, MatX::Zero(0, 3), 1), 3), 1e-12);
}

}  // namespace
}  // namespace sinew::engine

#include "functions/gcv_spline.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "common/error.h"
#include "finite_difference.h"

namespace sinew {
namespace {

// An independent form of the interpolating natural spline of degree 2m-1:
// s(x) = sum_j a_j |x - x_j|^(2m-1) + sum_{k<m} b_k x^k with sum_j a_j x_j^k = 0 (k < m),
// solved densely. Fine for a handful of well-spaced knots.
class RadialReference {
 public:
  RadialReference(int m, std::vector<double> x, std::vector<double> y) : m_(m), x_(std::move(x)) {
    const int n = static_cast<int>(x_.size());
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n + m, n + m);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n + m);
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) a(i, j) = std::pow(std::abs(x_[i] - x_[j]), 2 * m - 1);
      for (int k = 0; k < m; ++k) a(i, n + k) = a(n + k, i) = std::pow(x_[i], k);
      rhs(i) = y[i];
    }
    coefficients_ = a.fullPivLu().solve(rhs);
  }
  double Calc(double t) const {
    const int n = static_cast<int>(x_.size());
    double sum = 0.0;
    for (int j = 0; j < n; ++j) sum += coefficients_(j) * std::pow(std::abs(t - x_[j]), 2 * m_ - 1);
    for (int k = 0; k < m_; ++k) sum += coefficients_(n + k) * std::pow(t, k);
    return sum;
  }

 private:
  int m_;
  std::vector<double> x_;
  Eigen::VectorXd coefficients_;
};

// The corpus example (testControllers_TugOfWar.osim): half_order 3, error_variance 0.
const std::vector<double> kX = {0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1};
const std::vector<double> kY = {0.573621,   0.44629,   0.319214,   0.183898,  0.0920755, 0.0407125,
                                -0.0085371, -0.040781, -0.0774591, -0.133466, -0.219896};

TEST(GCVSplineTest, QuinticInterpolatesAndMatchesAnIndependentForm) {
  GCVSpline spline(3, kX, kY);
  RadialReference reference(3, kX, kY);
  for (size_t i = 0; i < kX.size(); ++i) EXPECT_NEAR(spline.Calc(kX[i]), kY[i], 1e-14);
  // Inside and outside the knots (outside: the natural quadratic continuation).
  for (double t = -0.3; t <= 1.3; t += 0.01) {
    EXPECT_NEAR(spline.Calc(t), reference.Calc(t), 1e-11) << t;
  }
}

TEST(GCVSplineTest, CubicCaseIsTheNaturalCubicSpline) {
  // half_order 2: the natural cubic spline, linear outside the knots.
  GCVSpline spline(2, {0.0, 1.0, 2.0, 3.0}, {0.0, 1.0, 0.0, 0.0});
  RadialReference reference(2, {0.0, 1.0, 2.0, 3.0}, {0.0, 1.0, 0.0, 0.0});
  for (double t = -1.0; t <= 4.0; t += 0.05) EXPECT_NEAR(spline.Calc(t), reference.Calc(t), 1e-13);
  GCVSpline three(2, {0.0, 1.0, 2.0, 3.0}, {0.0, 1.0, 2.0, 3.0});
  EXPECT_NEAR(three.Calc(5.0), 5.0, 1e-13);  // reproduces lines, extrapolates linearly
  EXPECT_NEAR(three.CalcDerivative(-1.0, 1), 1.0, 1e-13);
  EXPECT_EQ(three.CalcDerivative(-1.0, 2), 0.0);
}

TEST(GCVSplineTest, HandComputedNaturalCubic) {
  // Natural cubic through (0,0) (1,1) (2,0) (3,1): by symmetry-free hand solve of
  // 4 M1 + M2 = 6 (0 - 1 - 1) = -12, M1 + 4 M2 = 6 (1 + 1) = 12 -> M1 = -4, M2 = 4.
  // On [0, 1]: s = t + (M1 / 6)(t^3 - t) -> s(0.5) = 0.5 - (2/3)(0.125 - 0.5) = 0.75.
  GCVSpline spline(2, {0.0, 1.0, 2.0, 3.0}, {0.0, 1.0, 0.0, 1.0});
  EXPECT_NEAR(spline.Calc(0.5), 0.75, 1e-14);
  EXPECT_NEAR(spline.CalcDerivative(1.0, 2), -4.0, 1e-12);
  EXPECT_NEAR(spline.CalcDerivative(2.0, 2), 4.0, 1e-12);
}

TEST(GCVSplineTest, QuinticIsSmoothNaturalAndReproducesQuadratics) {
  GCVSpline spline(3, kX, kY);
  for (double t = 0.013; t < 1.0; t += 0.0487) {
    EXPECT_NEAR(spline.CalcDerivative(t, 1), testing::CentralDifference(spline, t, 1), 1e-8 * 10);
    EXPECT_NEAR(spline.CalcDerivative(t, 2), testing::CentralDifference(spline, t, 2), 1e-5);
  }
  // Natural ends: the third derivative vanishes at x0 (one-sided difference of s'').
  const double h = 1e-6;
  EXPECT_NEAR((spline.CalcDerivative(h, 2) - spline.CalcDerivative(0.0, 2)) / h, 0.0, 1e-3);
  // Second derivative continuous across the end knot into the quadratic continuation.
  EXPECT_NEAR(spline.CalcDerivative(-1e-9, 2), spline.CalcDerivative(0.0, 2), 1e-6);
  // Quadratics are in the natural quintic space: reproduced everywhere.
  std::vector<double> y;
  for (double t : kX) y.push_back(2.0 * t * t - t + 0.5);
  GCVSpline quadratic(3, kX, y);
  for (double t = -0.5; t <= 1.5; t += 0.1) {
    EXPECT_NEAR(quadratic.Calc(t), 2.0 * t * t - t + 0.5, 1e-12) << t;
  }
}

TEST(GCVSplineTest, RejectsWhatIsNotImplementedOrInvalid) {
  EXPECT_THROW(GCVSpline(3, kX, kY, 0.01), Error);  // smoothing
  EXPECT_THROW(GCVSpline(3, kX, kY, -1.0), Error);  // GCV
  EXPECT_THROW(GCVSpline(0, kX, kY), Error);
  EXPECT_THROW(GCVSpline(3, {0, 1, 2, 3, 4}, {0, 1, 2, 3, 4}), Error);  // needs 6 points
  EXPECT_THROW(GCVSpline(1, {0, 1, 1}, {0, 1, 2}), Error);              // not increasing
}

}  // namespace
}  // namespace sinew

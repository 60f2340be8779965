#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/functions/simm_spline.h>

#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "finite_difference.h"

namespace sinew {
namespace {

// An independent statement of the FMM spline: unknowns are the second derivatives M_i at the
// knots. Interior rows are C2 continuity; the end rows set the spline's third derivative on the
// first (last) interval, (M1 - M0) / h0, to that of the cubic through the first (last) four
// knots, 6 * f[x0, x1, x2, x3] (Newton divided differences). Evaluated with the textbook
// formula in terms of M. Needs >= 4 knots.
class FmmReference {
 public:
  FmmReference(std::vector<double> x, std::vector<double> y) : x_(std::move(x)), y_(std::move(y)) {
    const int n = static_cast<int>(x_.size());
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
    auto h = [&](int i) { return x_[i + 1] - x_[i]; };
    auto slope = [&](int i) { return (y_[i + 1] - y_[i]) / h(i); };
    for (int i = 1; i < n - 1; ++i) {
      a(i, i - 1) = h(i - 1);
      a(i, i) = 2.0 * (h(i - 1) + h(i));
      a(i, i + 1) = h(i);
      rhs(i) = 6.0 * (slope(i) - slope(i - 1));
    }
    a(0, 0) = -1.0 / h(0);
    a(0, 1) = 1.0 / h(0);
    rhs(0) = 6.0 * DividedDifference(0);
    a(n - 1, n - 2) = -1.0 / h(n - 2);
    a(n - 1, n - 1) = 1.0 / h(n - 2);
    rhs(n - 1) = 6.0 * DividedDifference(n - 4);
    m_ = a.fullPivLu().solve(rhs);
  }

  // Value inside [x0, x_{n-1}].
  double Calc(double t) const {
    int k = 0;
    while (k + 2 < static_cast<int>(x_.size()) && t > x_[k + 1]) ++k;
    const double h = x_[k + 1] - x_[k];
    const double a = (x_[k + 1] - t) / h;
    const double b = (t - x_[k]) / h;
    return a * y_[k] + b * y_[k + 1] +
           ((a * a * a - a) * m_(k) + (b * b * b - b) * m_(k + 1)) * h * h / 6.0;
  }

 private:
  // Third divided difference f[x_i, ..., x_{i+3}].
  double DividedDifference(int i) const {
    double f[4];
    for (int j = 0; j < 4; ++j) f[j] = y_[i + j];
    for (int level = 1; level < 4; ++level) {
      for (int j = 3; j >= level; --j) {
        f[j] = (f[j] - f[j - 1]) / (x_[i + j] - x_[i + j - level]);
      }
    }
    return f[3];
  }

  std::vector<double> x_, y_;
  Eigen::VectorXd m_;
};

// The natural cubic spline (M0 = M_{n-1} = 0), only to show it is a different function.
double NaturalSplineAt(const std::vector<double>& x, const std::vector<double>& y, double t) {
  const int n = static_cast<int>(x.size());
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  a(0, 0) = a(n - 1, n - 1) = 1.0;
  for (int i = 1; i < n - 1; ++i) {
    const double h0 = x[i] - x[i - 1], h1 = x[i + 1] - x[i];
    a(i, i - 1) = h0;
    a(i, i) = 2.0 * (h0 + h1);
    a(i, i + 1) = h1;
    rhs(i) = 6.0 * ((y[i + 1] - y[i]) / h1 - (y[i] - y[i - 1]) / h0);
  }
  Eigen::VectorXd m = a.fullPivLu().solve(rhs);
  int k = 0;
  while (k + 2 < n && t > x[k + 1]) ++k;
  const double h = x[k + 1] - x[k];
  const double p = (x[k + 1] - t) / h, q = (t - x[k]) / h;
  return p * y[k] + q * y[k + 1] +
         ((p * p * p - p) * m(k) + (q * q * q - q) * m(k + 1)) * h * h / 6;
}

// Knee translation data from OpenSim's MovingPathPointMomentArmTest.osim (y in m, x in rad).
const std::vector<double> kKneeX = {-2.0943951,  -1.99997279, -1.57079633, -1.45752446,
                                    -1.3962634,  -1.04719755, -0.78539816, -0.52359878,
                                    -0.34906585, -0.17453293, 0.0,         0.17453293};
const std::vector<double> kKneeY = {0.0082733,  0.01068662, 0.02020416, 0.02235298,
                                    0.02345827, 0.02927151, 0.03267044, 0.03493239,
                                    0.03583779, 0.03625744, 0.03616478, 0.03549306};

TEST(SimmSplineTest, MatchesAnIndependentFmmSolution) {
  functions::SimmSpline spline(kKneeX, kKneeY);
  FmmReference reference(kKneeX, kKneeY);
  double max_difference_from_natural = 0.0;
  for (int i = 0; i <= 400; ++i) {
    const double t = kKneeX.front() + (kKneeX.back() - kKneeX.front()) * i / 400.0;
    // Both are exact up to rounding in different algorithms on O(0.04) values.
    EXPECT_NEAR(spline.Calc(t), reference.Calc(t), 1e-15 * 100) << t;
    max_difference_from_natural = std::max(
        max_difference_from_natural, std::abs(spline.Calc(t) - NaturalSplineAt(kKneeX, kKneeY, t)));
  }
  // A natural spline differs visibly near the ends (the 2.5e-5 m effect seen on knees).
  EXPECT_GT(max_difference_from_natural, 1e-5);
}

TEST(SimmSplineTest, HandComputedFiveKnotCase) {
  // x = 0..4 (h = 1), y = 0 0 1 0 0, chord slopes delta = 0, 1, -1, 0. By hand, with FMM's
  // unknowns sigma_i = s''(x_i) / 6:
  //   third divided differences f[0,1,2,3] = -1/2 and f[1,2,3,4] = 1/2, so the end rows are
  //   sigma_1 - sigma_0 = -1/2 and sigma_4 - sigma_3 = 1/2;
  //   interior rows sigma_{i-1} + 4 sigma_i + sigma_{i+1} = delta_i - delta_{i-1} = 1, -2, 1.
  // By symmetry sigma = (a, b, c, b, a): b - a = -1/2, a + 4b + c = 1, 2b + 4c = -2
  //   -> b = 2/9, a = 13/18, c = -11/18.
  functions::SimmSpline spline({0, 1, 2, 3, 4}, {0, 0, 1, 0, 0});
  const double sigma[5] = {13.0 / 18.0, 2.0 / 9.0, -11.0 / 18.0, 2.0 / 9.0, 13.0 / 18.0};
  for (int i = 0; i < 5; ++i) {
    EXPECT_NEAR(spline.CalcDerivative(i, 2), 6.0 * sigma[i], 1e-14) << i;
  }
  // Slope at x0: delta_0 - h (sigma_1 + 2 sigma_0) = -(2/9 + 13/9) = -5/3.
  EXPECT_NEAR(spline.CalcDerivative(0.0, 1), -5.0 / 3.0, 1e-14);
  // Value at 0.5: b dx + 3 sigma_0 dx^2 + (sigma_1 - sigma_0) dx^3 = -5/6 + 13/24 - 1/16.
  EXPECT_NEAR(spline.Calc(0.5), -17.0 / 48.0, 1e-15);
  // The natural spline (s'' = 0 at the ends) is a different function here.
  EXPECT_GT(std::abs(spline.Calc(0.5) - NaturalSplineAt({0, 1, 2, 3, 4}, {0, 0, 1, 0, 0}, 0.5)),
            0.1);
}

TEST(SimmSplineTest, ReproducesCubicsExactly) {
  auto cubic = [](double t) { return 0.3 * t * t * t - 1.2 * t * t + 0.5 * t - 2.0; };
  std::vector<double> x = {-1.0, -0.2, 0.5, 0.6, 1.7, 2.0, 3.1};
  std::vector<double> y;
  for (double t : x) y.push_back(cubic(t));
  functions::SimmSpline spline(x, y);
  for (double t = -1.0; t <= 3.1; t += 0.01) {
    EXPECT_NEAR(spline.Calc(t), cubic(t), 1e-13) << t;
    EXPECT_NEAR(spline.CalcDerivative(t, 1), 0.9 * t * t - 2.4 * t + 0.5, 1e-12) << t;
    EXPECT_NEAR(spline.CalcDerivative(t, 2), 1.8 * t - 2.4, 1e-11) << t;
  }
  // With exactly four knots the spline is the cubic through them.
  functions::SimmSpline four({0.0, 1.0, 2.5, 3.0},
                             {cubic(0.0), cubic(1.0), cubic(2.5), cubic(3.0)});
  EXPECT_NEAR(four.Calc(1.7), cubic(1.7), 1e-13);
}

TEST(SimmSplineTest, ThreeKnotsGiveTheParabolaAndTwoKnotsTheLine) {
  functions::SimmSpline three({-1.0, 0.5, 2.0}, {1.0, 0.25, 4.0});  // y = x^2, unequal spacing
  for (double t = -1.0; t <= 2.0; t += 0.125) {
    EXPECT_NEAR(three.Calc(t), t * t, 1e-14) << t;
    EXPECT_NEAR(three.CalcDerivative(t, 2), 2.0, 1e-13) << t;
  }
  functions::SimmSpline two({0.0, 3.14159}, {-0.122564, -0.123775});
  const double slope = (-0.123775 + 0.122564) / 3.14159;
  EXPECT_NEAR(two.Calc(1.0), -0.122564 + slope, 1e-16);
  EXPECT_EQ(two.CalcDerivative(1.0, 1), slope);
  EXPECT_EQ(two.CalcDerivative(1.0, 2), 0.0);
}

TEST(SimmSplineTest, ExtrapolatesLinearlyWithTheEndSlopes) {
  functions::SimmSpline spline(kKneeX, kKneeY);
  const double slope0 = spline.CalcDerivative(kKneeX.front(), 1);
  const double slope1 = spline.CalcDerivative(kKneeX.back(), 1);
  EXPECT_NEAR(spline.Calc(-2.5), kKneeY.front() + (-2.5 - kKneeX.front()) * slope0, 1e-16);
  EXPECT_NEAR(spline.Calc(1.0), kKneeY.back() + (1.0 - kKneeX.back()) * slope1, 1e-16);
  EXPECT_EQ(spline.CalcDerivative(-2.5, 1), slope0);
  EXPECT_EQ(spline.CalcDerivative(1.0, 1), slope1);
  EXPECT_EQ(spline.CalcDerivative(-2.5, 2), 0.0);
  EXPECT_EQ(spline.CalcDerivative(1.0, 2), 0.0);
}

TEST(SimmSplineTest, ContinuousValueSlopeAndCurvatureAtKnots) {
  functions::SimmSpline spline(kKneeX, kKneeY);
  const auto& x = spline.x();
  for (size_t k = 1; k + 1 < x.size(); ++k) {
    // The polynomial of interval k-1 evaluated at its right end vs interval k at its left end.
    const double h = x[k] - x[k - 1];
    const double b = spline.b()[k - 1], c = spline.c()[k - 1], d = spline.d()[k - 1];
    EXPECT_NEAR(spline.y()[k - 1] + h * (b + h * (c + h * d)), spline.y()[k], 1e-16);
    EXPECT_NEAR(b + h * (2 * c + 3 * h * d), spline.b()[k], 1e-15);
    EXPECT_NEAR(2 * c + 6 * h * d, 2 * spline.c()[k], 1e-13);
  }
}

TEST(SimmSplineTest, DerivativesMatchFiniteDifferences) {
  functions::SimmSpline spline(kKneeX, kKneeY);
  for (double t = -2.05; t < 0.15; t += 0.0371) {
    // h = 1e-6: truncation ~h^2 * f''' ~ 1e-12, rounding ~1e-16 / 1e-6 ~ 1e-10 of the slope scale.
    EXPECT_NEAR(spline.CalcDerivative(t, 1), testing::CentralDifference(spline, t, 1), 1e-9);
    EXPECT_NEAR(spline.CalcDerivative(t, 2), testing::CentralDifference(spline, t, 2), 1e-7);
  }
}

// Breakpoints (rk45 ends a failing step at them): where the pieces on either side differ in their
// second or third derivative, the lines past the ends having neither.
TEST(SimmSplineTest, BreakpointsAreTheKnotsWhereThePiecesDiffer) {
  // A line: one piece, continued by the same line.
  EXPECT_TRUE(functions::SimmSpline({0.0, 1.0}, {1.0, 3.0}).Breakpoints().empty());
  // Three knots give one parabola (f'' = 2 throughout): only its ends, where f'' drops to 0.
  EXPECT_EQ(functions::SimmSpline({-1.0, 0.5, 2.0}, {1.0, 0.25, 4.0}).Breakpoints(),
            (std::vector<double>{-1.0, 2.0}));
  // FMM reproduces a cubic's data exactly: one cubic, so only its ends (f'' = 6 x there).
  std::vector<double> x, y;
  for (double t = 0.5; t < 3.1; t += 0.5) {
    x.push_back(t);
    y.push_back(t * t * t - 2.0 * t);
  }
  EXPECT_EQ(functions::SimmSpline(x, y).Breakpoints(), (std::vector<double>{0.5, 3.0}));
  // The knee's data: the third derivatives of neighbouring pieces (f'' differenced across each
  // piece's middle) all differ, so every knot is one.
  const functions::SimmSpline knee(kKneeX, kKneeY);
  EXPECT_TRUE(testing::ThirdDerivativeChangesAtEveryKnot(knee, kKneeX));
  EXPECT_EQ(knee.Breakpoints(), kKneeX);
}

TEST(SimmSplineTest, RejectsBadKnots) {
  EXPECT_THROW(functions::SimmSpline({0.0}, {1.0}), Error);
  EXPECT_THROW(functions::SimmSpline({0.0, 1.0}, {1.0}), Error);
  EXPECT_THROW(functions::SimmSpline({0.0, 2.0, 1.0}, {1.0, 2.0, 3.0}), Error);
  EXPECT_THROW(functions::SimmSpline({0.0, NAN}, {1.0, 2.0}), Error);
  EXPECT_THROW(functions::SimmSpline({0.0, 1.0}, {1.0, 2.0}).CalcDerivative(0.5, 3), Error);
  // Duplicate knots do not divide by zero (OpenSim raises spacings to 1e-7).
  functions::SimmSpline duplicate({0.0, 1.0, 1.0, 2.0}, {0.0, 1.0, 1.0, 0.0});
  EXPECT_TRUE(std::isfinite(duplicate.Calc(0.5)));
}

}  // namespace
}  // namespace sinew

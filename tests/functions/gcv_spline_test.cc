#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/functions/gcv_spline.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <random>
#include <vector>

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
  functions::GCVSpline spline(3, kX, kY);
  RadialReference reference(3, kX, kY);
  for (size_t i = 0; i < kX.size(); ++i) EXPECT_NEAR(spline.Calc(kX[i]), kY[i], 1e-14);
  // Inside and outside the knots (outside: the natural quadratic continuation).
  for (double t = -0.3; t <= 1.3; t += 0.01) {
    EXPECT_NEAR(spline.Calc(t), reference.Calc(t), 1e-11) << t;
  }
}

TEST(GCVSplineTest, CubicCaseIsTheNaturalCubicSpline) {
  // half_order 2: the natural cubic spline, linear outside the knots.
  functions::GCVSpline spline(2, {0.0, 1.0, 2.0, 3.0}, {0.0, 1.0, 0.0, 0.0});
  RadialReference reference(2, {0.0, 1.0, 2.0, 3.0}, {0.0, 1.0, 0.0, 0.0});
  for (double t = -1.0; t <= 4.0; t += 0.05) EXPECT_NEAR(spline.Calc(t), reference.Calc(t), 1e-13);
  functions::GCVSpline three(2, {0.0, 1.0, 2.0, 3.0}, {0.0, 1.0, 2.0, 3.0});
  EXPECT_NEAR(three.Calc(5.0), 5.0, 1e-13);  // reproduces lines, extrapolates linearly
  EXPECT_NEAR(three.CalcDerivative(-1.0, 1), 1.0, 1e-13);
  EXPECT_EQ(three.CalcDerivative(-1.0, 2), 0.0);
}

TEST(GCVSplineTest, HandComputedNaturalCubic) {
  // Natural cubic through (0,0) (1,1) (2,0) (3,1): by symmetry-free hand solve of
  // 4 M1 + M2 = 6 (0 - 1 - 1) = -12, M1 + 4 M2 = 6 (1 + 1) = 12 -> M1 = -4, M2 = 4.
  // On [0, 1]: s = t + (M1 / 6)(t^3 - t) -> s(0.5) = 0.5 - (2/3)(0.125 - 0.5) = 0.75.
  functions::GCVSpline spline(2, {0.0, 1.0, 2.0, 3.0}, {0.0, 1.0, 0.0, 1.0});
  EXPECT_NEAR(spline.Calc(0.5), 0.75, 1e-14);
  EXPECT_NEAR(spline.CalcDerivative(1.0, 2), -4.0, 1e-12);
  EXPECT_NEAR(spline.CalcDerivative(2.0, 2), 4.0, 1e-12);
}

TEST(GCVSplineTest, QuinticIsSmoothNaturalAndReproducesQuadratics) {
  functions::GCVSpline spline(3, kX, kY);
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
  functions::GCVSpline quadratic(3, kX, y);
  for (double t = -0.5; t <= 1.5; t += 0.1) {
    EXPECT_NEAR(quadratic.Calc(t), 2.0 * t * t - t + 0.5, 1e-12) << t;
  }
}

// Penalized least squares of a spline: sum (y - s(x_i))^2 + p * integral (s^(m))^2 for m = 1, 2
// (s' or s'' from the spline; exact 2-point Gauss per interval; zero outside the knots).
double SmoothingObjective(const functions::GCVSpline& s, const std::vector<double>& x,
                          const std::vector<double>& y, double p) {
  const int m = s.half_order();
  double sum = 0.0;
  for (size_t i = 0; i < x.size(); ++i) sum += std::pow(y[i] - s.Calc(x[i]), 2);
  double integral = 0.0;
  const double g = 1.0 / std::sqrt(3.0);
  for (size_t k = 0; k + 1 < x.size(); ++k) {
    const double mid = 0.5 * (x[k] + x[k + 1]), half = 0.5 * (x[k + 1] - x[k]);
    for (double t : {-g, g}) integral += half * std::pow(s.CalcDerivative(mid + t * half, m), 2);
  }
  return sum + p * integral;
}

// Noisy samples of a smooth function (uniform noise of half-width 0.05: variance 0.05^2 / 3).
struct NoisyData {
  std::vector<double> x, y, truth;
  double variance = 0.05 * 0.05 / 3.0;
};
NoisyData MakeNoisyData(int n) {
  NoisyData d;
  std::mt19937 random(12345);
  std::uniform_real_distribution<double> noise(-0.05, 0.05);
  for (int i = 0; i < n; ++i) {
    const double t = 0.02 * i;
    d.x.push_back(t);
    d.truth.push_back(std::sin(2.0 * t) + 0.5 * t);
    d.y.push_back(d.truth.back() + noise(random));
  }
  return d;
}

TEST(GCVSplineTest, SmoothingSplineMinimizesThePenalizedLeastSquares) {
  // For fixed p the fit must beat every other natural spline on the same knots: fits with other
  // p, the interpolant, and the fit to perturbed data. Checks the optimality rows (their sign
  // and scale) independently of how they were derived.
  NoisyData d = MakeNoisyData(30);
  for (int m : {1, 2}) {
    const double p = m == 1 ? 1e-3 : 1e-5;
    functions::GCVSpline best = functions::GCVSpline::WithSmoothingParameter(m, d.x, d.y, p);
    const double objective = SmoothingObjective(best, d.x, d.y, p);
    std::vector<double> perturbed = d.y;
    perturbed[7] += 0.01;
    for (const functions::GCVSpline& other :
         {functions::GCVSpline::WithSmoothingParameter(m, d.x, d.y, 0.5 * p),
          functions::GCVSpline::WithSmoothingParameter(m, d.x, d.y, 2.0 * p),
          functions::GCVSpline(m, d.x, d.y),
          functions::GCVSpline::WithSmoothingParameter(m, d.x, perturbed, p)}) {
      EXPECT_LT(objective, SmoothingObjective(other, d.x, d.y, p)) << m;
    }
    // Stationarity: a small change of the fit changes the objective only to second order.
    EXPECT_NEAR(
        objective,
        SmoothingObjective(
            functions::GCVSpline::WithSmoothingParameter(m, d.x, d.y, p * (1 + 1e-6)), d.x, d.y, p),
        1e-9 * objective);
  }
}

TEST(GCVSplineTest, SmoothingMatchesTheRadialFormAndLimits) {
  // Quintic smoothing spline in the radial form: (K + lambda I) a + T b = y, T' a = 0 with
  // K_ij = |x_i - x_j|^5 and lambda = (-1)^m 2 (2m-1)! p (the jump of s^(5) at x_i is 2 5! a_i).
  NoisyData d = MakeNoisyData(15);
  const int m = 3, n = 15;
  const double p = 1e-9;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n + m, n + m);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n + m);
  const double lambda = -2.0 * 120.0 * p;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) a(i, j) = std::pow(std::abs(d.x[i] - d.x[j]), 5);
    a(i, i) += lambda;
    for (int k = 0; k < m; ++k) a(i, n + k) = a(n + k, i) = std::pow(d.x[i], k);
    rhs(i) = d.y[i];
  }
  Eigen::VectorXd c = a.fullPivLu().solve(rhs);
  functions::GCVSpline spline = functions::GCVSpline::WithSmoothingParameter(m, d.x, d.y, p);
  for (double t = -0.1; t <= 0.4; t += 0.013) {
    double expected = 0.0;
    for (int j = 0; j < n; ++j) expected += c(j) * std::pow(std::abs(t - d.x[j]), 5);
    for (int k = 0; k < m; ++k) expected += c(n + k) * std::pow(t, k);
    EXPECT_NEAR(spline.Calc(t), expected, 1e-9) << t;
  }
  // A very stiff cubic smoothing spline is the least-squares line.
  functions::GCVSpline stiff = functions::GCVSpline::WithSmoothingParameter(2, d.x, d.y, 1e6);
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int i = 0; i < n; ++i) {
    sx += d.x[i], sy += d.y[i], sxx += d.x[i] * d.x[i], sxy += d.x[i] * d.y[i];
  }
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  const double intercept = (sy - slope * sx) / n;
  for (double t : {0.0, 0.1, 0.28}) EXPECT_NEAR(stiff.Calc(t), intercept + slope * t, 1e-6);
}

TEST(GCVSplineTest, ErrorVarianceAndGcvChooseTheCriterionMinimum) {
  NoisyData d = MakeNoisyData(40);
  for (double error_variance : {d.variance, -1.0}) {
    functions::GCVSpline fit(3, d.x, d.y, error_variance);
    const double p = fit.smoothing_parameter();
    ASSERT_GT(p, 0.0);
    const double at_p =
        functions::GCVSpline::CalcSmoothingCriterion(3, d.x, d.y, error_variance, p);
    for (double factor : {0.9, 1.1, 0.5, 2.0}) {
      EXPECT_LE(at_p, functions::GCVSpline::CalcSmoothingCriterion(3, d.x, d.y, error_variance,
                                                                   p * factor) +
                          1e-15)
          << error_variance << " " << factor;
    }
    // The smoothed curve is closer to the truth than the noisy samples are.
    double data_error = 0.0, fit_error = 0.0;
    for (size_t i = 0; i < d.x.size(); ++i) {
      data_error += std::pow(d.y[i] - d.truth[i], 2);
      fit_error += std::pow(fit.Calc(d.x[i]) - d.truth[i], 2);
    }
    EXPECT_LT(fit_error, 0.5 * data_error) << error_variance;
  }
  EXPECT_EQ(functions::GCVSpline(3, d.x, d.y, 0.0).smoothing_parameter(), 0.0);
}

// ---- The smoothing criterion against independent dense computations ----
//
// For a smoothing spline the fitted values are linear in the data, y_hat = A(p) y, and
// (Craven & Wahba 1979; Woltring's GCVSPL, routine SPLC) with RSS = |(I - A) y|^2:
//   GCV(p) = (RSS/n) / (tr(I - A)/n)^2,   R(p) = RSS/n - s2 (2 tr(I - A)/n - 1).
// Here I - A is formed densely by three constructions that share nothing with the library's
// banded piecewise-polynomial system.

// Criterion value from the dense residual operator I - A.
double CriterionFromResidualOperator(const Eigen::MatrixXd& I_minus_A, const std::vector<double>& y,
                                     double error_variance) {
  const double n = static_cast<double>(y.size());
  const Eigen::VectorXd residual =
      I_minus_A * Eigen::Map<const Eigen::VectorXd>(y.data(), y.size());
  const double mean_residual = residual.squaredNorm() / n;
  const double trace_fraction = I_minus_A.trace() / n;
  if (error_variance < 0.0) return mean_residual / (trace_fraction * trace_fraction);
  return mean_residual - error_variance * (2.0 * trace_fraction - 1.0);
}

// m = 1: s is the broken line through the fitted values g, and integral s'^2 =
// sum (g_{i+1} - g_i)^2 / h_i = g' D g (D the path Laplacian with weights 1/h_i). Minimizing
// |y - g|^2 + p g' D g gives g = (I + p D)^-1 y.
Eigen::MatrixXd LinearResidualOperator(const std::vector<double>& x, double p) {
  const int n = static_cast<int>(x.size());
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i + 1 < n; ++i) {
    const double w = 1.0 / (x[i + 1] - x[i]);
    D(i, i) += w, D(i + 1, i + 1) += w, D(i, i + 1) -= w, D(i + 1, i) -= w;
  }
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(n, n);
  return I - (I + p * D).inverse();
}

// m = 2: Reinsch's form (Green & Silverman 1994, section 2.3): integral s''^2 = g' K g with
// K = Q R^-1 Q', Q (n x n-2) the second divided differences (1/h_{j-1}, -1/h_{j-1} - 1/h_j,
// 1/h_j) and R (n-2 x n-2) tridiagonal ((h_{j-1} + h_j)/3 on the diagonal, h_j/6 beside it).
Eigen::MatrixXd CubicResidualOperator(const std::vector<double>& x, double p) {
  const int n = static_cast<int>(x.size());
  Eigen::MatrixXd Q = Eigen::MatrixXd::Zero(n, n - 2), R = Eigen::MatrixXd::Zero(n - 2, n - 2);
  for (int j = 1; j + 1 < n; ++j) {
    const double h0 = x[j] - x[j - 1], h1 = x[j + 1] - x[j];
    Q(j - 1, j - 1) = 1.0 / h0;
    Q(j, j - 1) = -1.0 / h0 - 1.0 / h1;
    Q(j + 1, j - 1) = 1.0 / h1;
    R(j - 1, j - 1) = (h0 + h1) / 3.0;
    if (j + 2 < n) R(j - 1, j) = R(j, j - 1) = h1 / 6.0;
  }
  const Eigen::MatrixXd K = Q * R.ldlt().solve(Q.transpose());
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(n, n);
  return I - (I + p * K).inverse();
}

// m = 3: the radial form s = sum_j a_j |x - x_j|^5 + b0 + b1 x + b2 x^2 with sum_j a_j x_j^k = 0.
// The jump of s^(5) at x_i is 2 5! a_i, so the optimality condition s(x_i) + p (-1)^m (jump) =
// y_i reads (K + lambda I) a + T b = y with lambda = -240 p, and y - y_hat = lambda a: I - A is
// lambda times the top-left n x n block of the inverse of [K + lambda I, T; T', 0].
Eigen::MatrixXd QuinticResidualOperator(const std::vector<double>& x, double p) {
  const int n = static_cast<int>(x.size()), m = 3;
  const double lambda = -240.0 * p;
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n + m, n + m);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) M(i, j) = std::pow(std::abs(x[i] - x[j]), 5);
    M(i, i) += lambda;
    for (int k = 0; k < m; ++k) M(i, n + k) = M(n + k, i) = std::pow(x[i], k);
  }
  return lambda * M.fullPivLu().inverse().topLeftCorner(n, n);
}

Eigen::MatrixXd ResidualOperator(int m, const std::vector<double>& x, double p) {
  if (m == 1) return LinearResidualOperator(x, p);
  if (m == 2) return CubicResidualOperator(x, p);
  return QuinticResidualOperator(x, p);
}

// Fourteen unevenly spaced points about 1 apart with noise of variance 0.2^2 / 3.
NoisyData MakeUnevenData() {
  NoisyData d;
  std::mt19937 random(2024);
  std::uniform_real_distribution<double> noise(-0.2, 0.2);
  for (int i = 0; i < 14; ++i) {
    d.x.push_back(i + 0.25 * std::sin(1.3 * i));
    d.truth.push_back(std::sin(0.6 * d.x.back()));
    d.y.push_back(d.truth.back() + noise(random));
  }
  d.variance = 0.2 * 0.2 / 3.0;
  return d;
}

TEST(GCVSplineTest, CriterionMatchesDenseInfluenceMatrices) {
  const NoisyData d = MakeUnevenData();
  double worst = 0.0;
  for (int m : {1, 2, 3}) {
    // p over six decades around the natural scale h^(2m-1) / (2m-1)! (h = 1 here).
    const double p0 = m == 1 ? 1.0 : m == 2 ? 1.0 / 6.0 : 1.0 / 120.0;
    for (double decades = -3.0; decades <= 3.0; decades += 0.5) {
      const double p = p0 * std::pow(10.0, decades);
      const Eigen::MatrixXd I_minus_A = ResidualOperator(m, d.x, p);
      for (double error_variance : {d.variance, -1.0}) {
        const double expected = CriterionFromResidualOperator(I_minus_A, d.y, error_variance);
        const double actual =
            functions::GCVSpline::CalcSmoothingCriterion(m, d.x, d.y, error_variance, p);
        // Direct solves of well-conditioned systems (unit spacing, p near its scale) on both
        // sides: agreement to rounding, far below 1e-9 relative.
        EXPECT_NEAR(actual, expected, 1e-9 * std::abs(expected))
            << "m = " << m << ", p = " << p << ", error_variance = " << error_variance;
        worst = std::max(worst, std::abs(actual - expected) / std::abs(expected));
      }
    }
  }
  std::cout << "largest relative difference from the dense criteria: " << worst << "\n";
}

TEST(GCVSplineTest, ChosenSmoothingMinimizesTheDenseCriterion) {
  // The fit's p must minimize the independently computed criterion: no point of a grid of
  // 0.01 decades over p0 10^-9 .. p0 10^3 may beat it (beyond that the radial form loses its
  // accuracy: lambda = -240 p swamps K). p = 0 (interpolation) is right when the criterion
  // falls towards p -> 0: then the lowest grid point must be the best.
  const NoisyData d = MakeUnevenData();
  int interpolating = 0;
  for (int m : {2, 3}) {
    const double p0 = m == 2 ? 1.0 / 6.0 : 1.0 / 120.0;
    for (double error_variance : {d.variance, -1.0}) {
      const double p = functions::GCVSpline(m, d.x, d.y, error_variance).smoothing_parameter();
      auto criterion = [&](double q) {
        return CriterionFromResidualOperator(ResidualOperator(m, d.x, q), d.y, error_variance);
      };
      const double at_p = criterion(p > 0.0 ? p : p0 * 1e-9);
      interpolating += p == 0.0;
      double best = std::numeric_limits<double>::infinity();
      for (int k = -900; k <= 300; ++k)
        best = std::min(best, criterion(p0 * std::pow(10.0, k / 100.0)));
      // The criterion agrees with the dense form to ~1e-11 (test above) and the search stops
      // at 1e-9 decades, where the criterion is flat to second order.
      EXPECT_LE(at_p, best * (1 + 1e-9))
          << "m = " << m << ", error_variance = " << error_variance << ", p = " << p;
      std::cout << "m = " << m << ", error_variance = " << error_variance << ": p = " << p
                << ", criterion " << at_p << " (grid minimum " << best << ")\n";
    }
  }
  EXPECT_LT(interpolating, 4);  // the data are noisy: smoothing wins at least once
}

// Breakpoints (rk45 ends a failing step at them): a cubic's knots, where its pieces' third
// derivatives differ (its ends too: the natural spline's f'' is 0 there, but not its f''', and
// the line outside has none); none for a quintic.
TEST(GCVSplineTest, BreakpointsAreACubicsKnots) {
  const functions::GCVSpline cubic(2, kX, kY, 0.0);
  EXPECT_TRUE(testing::ThirdDerivativeChangesAtEveryKnot(cubic, kX));
  EXPECT_EQ(cubic.Breakpoints(), kX);
  EXPECT_TRUE(functions::GCVSpline(3, kX, kY, 0.0).Breakpoints().empty());
}

TEST(GCVSplineTest, RejectsInvalidInput) {
  EXPECT_THROW(functions::GCVSpline(0, kX, kY), Error);
  EXPECT_THROW(functions::GCVSpline(5, kX, kY), Error);
  EXPECT_THROW(functions::GCVSpline(3, {0, 1, 2, 3, 4}, {0, 1, 2, 3, 4}), Error);  // needs 6 points
  EXPECT_THROW(functions::GCVSpline(1, {0, 1, 1}, {0, 1, 2}), Error);              // not increasing
  EXPECT_THROW(functions::GCVSpline::WithSmoothingParameter(3, kX, kY, -1.0), Error);
}

}  // namespace
}  // namespace sinew

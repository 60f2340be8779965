// Value and derivative tests for the simple OpenSim function types, against hand-computed values
// and finite differences.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/functions/constant.h>
#include <sinew/functions/linear_function.h>
#include <sinew/functions/multiplier_function.h>
#include <sinew/functions/multivariate_polynomial_function.h>
#include <sinew/functions/piecewise_constant_function.h>
#include <sinew/functions/piecewise_linear_function.h>
#include <sinew/functions/polynomial_function.h>
#include <sinew/functions/simm_spline.h>
#include <sinew/functions/sine.h>
#include <sinew/functions/step_function.h>

#include <array>
#include <cmath>
#include <memory>
#include <numbers>

#include "finite_difference.h"

namespace sinew {
namespace {

using testing::CentralDifference;

// Checks first and second derivatives of a smooth f against central differences at `points`.
void ExpectDerivativesMatchFiniteDifferences(const functions::Function& f,
                                             std::initializer_list<double> points,
                                             double tolerance) {
  for (double x : points) {
    EXPECT_NEAR(f.CalcDerivative(x, 1), CentralDifference(f, x, 1), tolerance) << f.TypeName() << x;
    EXPECT_NEAR(f.CalcDerivative(x, 2), CentralDifference(f, x, 2), tolerance) << f.TypeName() << x;
    EXPECT_EQ(f.CalcDerivative(x, 0), f.Calc(x));
  }
}

TEST(FunctionTypesTest, Constant) {
  functions::Constant f(0.0027499999999999998);
  EXPECT_EQ(f.Calc(-3.0), 0.0027499999999999998);
  EXPECT_EQ(f.CalcDerivative(1.0, 1), 0.0);
  EXPECT_EQ(f.CalcDerivative(1.0, 2), 0.0);
  EXPECT_THROW(f.CalcDerivative(1.0, 3), Error);
}

TEST(FunctionTypesTest, LinearFunctionIsSlopeThenIntercept) {
  functions::LinearFunction f(-0.333333, 1.0);
  EXPECT_DOUBLE_EQ(f.Calc(3.0), 1.0 - 0.999999);
  EXPECT_EQ(f.CalcDerivative(3.0, 1), -0.333333);
  EXPECT_EQ(f.CalcDerivative(3.0, 2), 0.0);
  EXPECT_EQ(functions::LinearFunction().Calc(0.7), 0.7);  // default: identity
}

TEST(FunctionTypesTest, PolynomialCoefficientsAreInDecreasingPowers) {
  // From RajagopalLaiUhlrich2023.osim: 0.0252 x^3 - 0.1695 x^2 + 0.3695 x - 4.43e-8.
  functions::PolynomialFunction f(
      {0.025165762727423002, -0.16948005139054001, 0.36949934868824902, -4.4303583088363053e-08});
  const double x = 1.2;
  const double a = 0.025165762727423002, b = -0.16948005139054001, c = 0.36949934868824902,
               d = -4.4303583088363053e-08;
  EXPECT_NEAR(f.Calc(x), a * x * x * x + b * x * x + c * x + d, 1e-16);
  EXPECT_NEAR(f.CalcDerivative(x, 1), 3 * a * x * x + 2 * b * x + c, 1e-16);
  EXPECT_NEAR(f.CalcDerivative(x, 2), 6 * a * x + 2 * b, 1e-16);
  EXPECT_NEAR(f.CalcDerivative(x, 3), 6 * a, 1e-16);
  EXPECT_EQ(f.CalcDerivative(x, 4), 0.0);
  EXPECT_EQ(functions::PolynomialFunction({}).Calc(2.0), 0.0);
  ExpectDerivativesMatchFiniteDifferences(f, {-1.0, 0.0, 0.5, 2.0}, 1e-8);
}

TEST(FunctionTypesTest, MultiplierScalesValueAndDerivatives) {
  auto inner = std::make_shared<functions::PolynomialFunction>(std::vector<double>{1.0, -2.0, 0.5});
  functions::MultiplierFunction f(inner, 0.99999644921000319);
  for (int order = 0; order <= 2; ++order) {
    EXPECT_EQ(f.CalcDerivative(0.3, order),
              0.99999644921000319 * inner->CalcDerivative(0.3, order));
  }
  EXPECT_THROW(functions::MultiplierFunction(nullptr, 1.0), Error);
}

TEST(FunctionTypesTest, PiecewiseLinearExtrapolatesWithTheEndSlopes) {
  functions::PiecewiseLinearFunction f({-1.0, 0.0, 2.0}, {0.0, 1.0, 0.0});
  EXPECT_EQ(f.Calc(-1.0), 0.0);
  EXPECT_EQ(f.Calc(-0.5), 0.5);
  EXPECT_EQ(f.Calc(1.0), 0.5);
  EXPECT_EQ(f.Calc(-3.0), -2.0);  // slope 1 continued
  EXPECT_EQ(f.Calc(4.0), -1.0);   // slope -1/2 continued
  EXPECT_EQ(f.CalcDerivative(-3.0, 1), 1.0);
  EXPECT_EQ(f.CalcDerivative(0.5, 1), -0.5);
  EXPECT_EQ(f.CalcDerivative(5.0, 1), -0.5);
  EXPECT_EQ(f.CalcDerivative(0.5, 2), 0.0);
  // Exactly on an interior knot the slope is that of the segment OpenSim's bisection lands on:
  // for five knots and x = x[3] the first probe k = 2 stops, giving the LEFT segment's slope.
  functions::PiecewiseLinearFunction g({0.0, 1.0, 2.0, 3.0, 4.0}, {0.0, 1.0, 3.0, 6.0, 10.0});
  EXPECT_EQ(g.CalcDerivative(3.0, 1), 3.0);
  EXPECT_EQ(g.CalcDerivative(3.0 + 1e-12, 1), 4.0);
  EXPECT_EQ(g.Calc(3.0), 6.0);
  ExpectDerivativesMatchFiniteDifferences(g, {0.5, 1.5, 2.7}, 1e-8);
}

TEST(FunctionTypesTest, PiecewiseConstantHoldsEachValueUntilTheNextKnot) {
  functions::PiecewiseConstantFunction f({0.0, 1.0, 2.0, 3.0}, {10.0, 20.0, 30.0, 40.0});
  EXPECT_EQ(f.Calc(-1.0), 10.0);
  EXPECT_EQ(f.Calc(0.0), 10.0);
  EXPECT_EQ(f.Calc(0.5), 10.0);
  EXPECT_EQ(f.Calc(1.5), 20.0);
  EXPECT_EQ(f.Calc(2.999), 30.0);
  EXPECT_EQ(f.Calc(3.0), 40.0);
  EXPECT_EQ(f.Calc(7.0), 40.0);
  // Exactly on an interior knot the result is whatever OpenSim's bisection (low = 0, high = n,
  // k = (low + high) / 2, stop when x[k] <= v <= x[k+1]) lands on. v = 1: k = 2 (v < x[2]),
  // then k = 1 stops -> y[1]. v = 2: k = 2 stops at once -> y[2].
  EXPECT_EQ(f.Calc(1.0), 20.0);
  EXPECT_EQ(f.Calc(2.0), 30.0);
  // With five knots, v = x[3] = 3: the first probe k = 2 already has x[2] <= 3 <= x[3], so the
  // value is y[2], the LEFT side of the knot.
  functions::PiecewiseConstantFunction five({0.0, 1.0, 2.0, 3.0, 4.0},
                                            {10.0, 20.0, 30.0, 40.0, 50.0});
  EXPECT_EQ(five.Calc(3.0), 30.0);
  EXPECT_EQ(five.Calc(3.0 + 1e-12), 40.0);
  EXPECT_EQ(f.CalcDerivative(0.5, 1), 0.0);
  EXPECT_EQ(functions::PiecewiseConstantFunction({1.0}, {5.0}).Calc(0.0), 5.0);
}

TEST(FunctionTypesTest, StepFunctionIsSimbodysQuinticStep) {
  functions::StepFunction f(1.0, 3.0, 2.0, 6.0);
  EXPECT_EQ(f.Calc(0.0), 2.0);
  EXPECT_EQ(f.Calc(1.0), 2.0);
  EXPECT_EQ(f.Calc(3.0), 6.0);
  EXPECT_EQ(f.Calc(9.0), 6.0);
  // s = 0.5: 10/8 - 15/16 + 6/32 = 1/2.
  EXPECT_DOUBLE_EQ(f.Calc(2.0), 4.0);
  // s = 0.25: 10/64 - 15/256 + 6/1024 = 106/1024.
  EXPECT_DOUBLE_EQ(f.Calc(1.5), 2.0 + 4.0 * 106.0 / 1024.0);
  // Slope at the middle: 30 s^2 (1-s)^2 / width * rise = 30/16 / 2 * 4 = 3.75.
  EXPECT_DOUBLE_EQ(f.CalcDerivative(2.0, 1), 3.75);
  EXPECT_NEAR(f.CalcDerivative(2.0, 2), 0.0, 1e-15);
  EXPECT_EQ(f.CalcDerivative(0.5, 1), 0.0);
  ExpectDerivativesMatchFiniteDifferences(f, {1.1, 1.5, 2.2, 2.9}, 1e-7);
  // Backwards transition and the OpenSim defaults 0.99 -> 1.01, 0 -> 1.
  functions::StepFunction backwards(3.0, 1.0, 2.0, 6.0);
  EXPECT_EQ(backwards.Calc(3.5), 2.0);
  EXPECT_EQ(backwards.Calc(0.5), 6.0);
  EXPECT_DOUBLE_EQ(backwards.Calc(2.5), 2.0 + 4.0 * 106.0 / 1024.0);
  EXPECT_THROW(functions::StepFunction(1.0, 1.0, 0.0, 1.0), Error);
}

TEST(FunctionTypesTest, Sine) {
  functions::Sine f(2.0, 3.0, 0.5, 1.0);
  EXPECT_DOUBLE_EQ(f.Calc(0.2), 2.0 * std::sin(0.6 + 0.5) + 1.0);
  EXPECT_DOUBLE_EQ(f.CalcDerivative(0.2, 1), 6.0 * std::cos(1.1));
  EXPECT_DOUBLE_EQ(f.CalcDerivative(0.2, 2), -18.0 * std::sin(1.1));
  ExpectDerivativesMatchFiniteDifferences(f, {-1.0, 0.0, 0.3, 2.0}, 1e-7);
}

TEST(FunctionTypesTest, MultivariatePolynomialUsesOpenSimsCoefficientOrder) {
  // dimension 3, order 2: terms (0,0,0) (0,0,1) (0,0,2) (0,1,0) (0,1,1) (0,2,0) (1,0,0) (1,0,1)
  // (1,1,0) (2,0,0) over (X, Y, Z).
  std::vector<double> c = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
  functions::MultivariatePolynomialFunction f(c, 3, 2);
  ASSERT_EQ(f.NumArguments(), 3);
  const std::array<double, 3> p = {0.5, -1.5, 2.0};
  const double X = p[0], Y = p[1], Z = p[2];
  const double expected = 1 + 2 * Z + 3 * Z * Z + 4 * Y + 5 * Y * Z + 6 * Y * Y + 7 * X +
                          8 * X * Z + 9 * X * Y + 10 * X * X;
  EXPECT_NEAR(f.CalcN(p), expected, 1e-13);
  const std::array<int, 1> d_x = {0};
  EXPECT_NEAR(f.CalcPartialN(p, d_x), 7 + 8 * Z + 9 * Y + 20 * X, 1e-13);
  const std::array<int, 2> d_yz = {1, 2};
  EXPECT_NEAR(f.CalcPartialN(p, d_yz), 5.0, 1e-13);
  const std::array<int, 2> d_zz = {2, 2};
  EXPECT_NEAR(f.CalcPartialN(p, d_zz), 6.0, 1e-13);
  // The corpus example: dimension 3, order 1, all ones -> 1 + Z + Y + X.
  functions::MultivariatePolynomialFunction linear({1, 1, 1, 1}, 3, 1);
  EXPECT_NEAR(linear.CalcN(p), 1 + X + Y + Z, 1e-15);
  EXPECT_THROW(functions::MultivariatePolynomialFunction({1, 2, 3}, 3, 1), Error);
  EXPECT_THROW(f.Calc(1.0), Error);  // three arguments needed
}

}  // namespace
}  // namespace sinew

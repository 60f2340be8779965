// Tiny Function subclasses for kinematics tests (so the tests need no other layer's classes).
#pragma once

#include <sinew/functions/function.h>

#include <cmath>
#include <memory>
#include <span>
#include <string>

namespace sinew::testing {

/// f(x) = a + b x + c x^2 + d sin(x): smooth, with non-zero first and second derivatives.
class TestSmoothFunction final : public functions::Function {
 public:
  TestSmoothFunction(double a, double b, double c, double d) : a_(a), b_(b), c_(c), d_(d) {}
  std::string TypeName() const override { return "TestSmoothFunction"; }
  double Calc(double x) const override { return a_ + b_ * x + c_ * x * x + d_ * std::sin(x); }
  double CalcDerivative(double x, int order) const override {
    if (order == 0) return Calc(x);
    if (order == 1) return b_ + 2 * c_ * x + d_ * std::cos(x);
    return 2 * c_ - d_ * std::sin(x);
  }

 private:
  double a_, b_, c_, d_;
};

/// f(x0, x1) = x0 * x1 + 0.3 sin(x0) - 0.2 x1^2: a two-argument coupling.
class TestTwoArgFunction final : public functions::Function {
 public:
  std::string TypeName() const override { return "TestTwoArgFunction"; }
  int NumArguments() const override { return 2; }
  double Calc(double) const override { return 0.0; }
  double CalcDerivative(double, int) const override { return 0.0; }
  double CalcN(std::span<const double> x) const override {
    return x[0] * x[1] + 0.3 * std::sin(x[0]) - 0.2 * x[1] * x[1];
  }
  double CalcPartialN(std::span<const double> x, std::span<const int> wrt) const override {
    if (wrt.size() == 1) {
      return wrt[0] == 0 ? x[1] + 0.3 * std::cos(x[0]) : x[0] - 0.4 * x[1];
    }
    if (wrt[0] == 0 && wrt[1] == 0) return -0.3 * std::sin(x[0]);
    if (wrt[0] == 1 && wrt[1] == 1) return -0.4;
    return 1.0;
  }
};

/// f = value (any number of arguments).
class TestConstantFunction final : public functions::Function {
 public:
  explicit TestConstantFunction(double value) : value_(value) {}
  std::string TypeName() const override { return "Constant"; }
  double Calc(double) const override { return value_; }
  double CalcDerivative(double, int order) const override { return order == 0 ? value_ : 0.0; }

 private:
  double value_;
};

/// f(x) = slope x + intercept.
class TestLinearFunction final : public functions::Function {
 public:
  TestLinearFunction(double slope, double intercept) : slope_(slope), intercept_(intercept) {}
  std::string TypeName() const override { return "LinearFunction"; }
  double Calc(double x) const override { return slope_ * x + intercept_; }
  double CalcDerivative(double x, int order) const override {
    return order == 0 ? Calc(x) : (order == 1 ? slope_ : 0.0);
  }

 private:
  double slope_, intercept_;
};

}  // namespace sinew::testing

// OpenSim's PolynomialFunction.
#pragma once

#include <sinew/functions/function.h>

#include <vector>

namespace sinew::functions {

/// f(x) = c[0] x^(n-1) + c[1] x^(n-2) + ... + c[n-1]: OpenSim's `coefficients` in DECREASING
/// powers (the last one is the constant term). An empty list is the zero polynomial.
class PolynomialFunction final : public Function {
 public:
  explicit PolynomialFunction(std::vector<double> coefficients)
      : coefficients_(std::move(coefficients)) {}

  std::string TypeName() const override { return "PolynomialFunction"; }
  double Calc(double x) const override { return CalcDerivative(x, 0); }
  /// Exact derivative of any order >= 0 (Horner's scheme on the differentiated coefficients).
  double CalcDerivative(double x, int order) const override;

  const std::vector<double>& coefficients() const { return coefficients_; }

 private:
  std::vector<double> coefficients_;
};

}  // namespace sinew::functions

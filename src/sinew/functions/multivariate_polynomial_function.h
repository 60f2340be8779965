// OpenSim's MultivariatePolynomialFunction.
#pragma once

#include <sinew/functions/function.h>

#include <vector>

namespace sinew::functions {

/// A polynomial in `dimension` variables (x0, x1, ...) with every term of total degree <=
/// `order`. OpenSim's coefficient order: ascending powers with the LAST variable running
/// fastest, i.e. the exponent tuples (e0, e1, ..., e_{d-1}) in lexicographic order over
/// e0 + ... <= order. For three variables X, Y, Z and order 1: c0 + c1 Z + c2 Y + c3 X.
/// There must be exactly C(order + dimension, dimension) coefficients (throws otherwise).
/// Partial derivatives of any order are exact.
class MultivariatePolynomialFunction final : public Function {
 public:
  MultivariatePolynomialFunction(std::vector<double> coefficients, int dimension, int order);

  std::string TypeName() const override { return "MultivariatePolynomialFunction"; }
  int NumArguments() const override { return dimension_; }
  /// Only for dimension 1; throws otherwise.
  double Calc(double x) const override;
  /// Only for dimension 1; throws otherwise.
  double CalcDerivative(double x, int order) const override;
  double CalcN(std::span<const double> x) const override;
  double CalcPartialN(std::span<const double> x, std::span<const int> wrt) const override;

  const std::vector<double>& coefficients() const { return coefficients_; }
  int dimension() const { return dimension_; }
  int order() const { return order_; }
  /// The exponents of term i: exponents()[i * dimension() + d] is the power of x_d.
  const std::vector<int>& exponents() const { return exponents_; }

 private:
  std::vector<double> coefficients_;
  int dimension_;
  int order_;
  std::vector<int> exponents_;
};

}  // namespace sinew::functions

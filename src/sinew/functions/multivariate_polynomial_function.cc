#include <sinew/common/error.h>
#include <sinew/functions/multivariate_polynomial_function.h>

#include <array>

namespace sinew::functions {
namespace {

// Appends the exponent tuples of total degree <= `budget` for variables d.. in OpenSim's order
// (lexicographic, last variable fastest).
void ListExponents(int d, int budget, std::vector<int>& tuple, std::vector<int>& out) {
  const int dimension = static_cast<int>(tuple.size());
  if (d == dimension) {
    out.insert(out.end(), tuple.begin(), tuple.end());
    return;
  }
  for (int e = 0; e <= budget; ++e) {
    tuple[d] = e;
    ListExponents(d + 1, budget - e, tuple, out);
  }
  tuple[d] = 0;
}

}  // namespace

MultivariatePolynomialFunction::MultivariatePolynomialFunction(std::vector<double> coefficients,
                                                               int dimension, int order)
    : coefficients_(std::move(coefficients)), dimension_(dimension), order_(order) {
  if (dimension_ < 1) {
    throw Error("MultivariatePolynomialFunction: dimension must be >= 1, got " +
                std::to_string(dimension_));
  }
  if (order_ < 0) {
    throw Error("MultivariatePolynomialFunction: order must be >= 0, got " +
                std::to_string(order_));
  }
  std::vector<int> tuple(dimension_, 0);
  ListExponents(0, order_, tuple, exponents_);
  const size_t terms = exponents_.size() / dimension_;
  if (coefficients_.size() != terms) {
    throw Error("MultivariatePolynomialFunction: dimension " + std::to_string(dimension_) +
                " and order " + std::to_string(order_) + " need " + std::to_string(terms) +
                " coefficients, got " + std::to_string(coefficients_.size()));
  }
}

double MultivariatePolynomialFunction::Calc(double x) const {
  return CalcPartialN(std::span<const double>(&x, 1), {});
}

double MultivariatePolynomialFunction::CalcDerivative(double x, int order) const {
  if (order < 0 || order > 2) {
    throw Error("MultivariatePolynomialFunction: derivative order must be 0, 1 or 2");
  }
  const std::array<int, 2> wrt = {0, 0};
  return CalcPartialN(std::span<const double>(&x, 1), std::span<const int>(wrt.data(), order));
}

double MultivariatePolynomialFunction::CalcN(std::span<const double> x) const {
  return CalcPartialN(x, {});
}

double MultivariatePolynomialFunction::CalcPartialN(std::span<const double> x,
                                                    std::span<const int> wrt) const {
  if (static_cast<int>(x.size()) != dimension_) {
    throw Error("MultivariatePolynomialFunction: expects " + std::to_string(dimension_) +
                " arguments, got " + std::to_string(x.size()));
  }
  // How many times to differentiate by each variable.
  std::vector<int> times(dimension_, 0);
  for (int d : wrt) {
    if (d < 0 || d >= dimension_) {
      throw Error("MultivariatePolynomialFunction: no argument " + std::to_string(d));
    }
    ++times[d];
  }
  double sum = 0.0;
  for (size_t term = 0; term < coefficients_.size(); ++term) {
    double value = coefficients_[term];
    for (int d = 0; d < dimension_ && value != 0.0; ++d) {
      const int power = exponents_[term * dimension_ + d];
      if (times[d] > power) {
        value = 0.0;
        break;
      }
      // d^k/dx^k x^p = p (p-1) ... (p-k+1) x^(p-k).
      for (int k = 0; k < times[d]; ++k) value *= power - k;
      for (int k = times[d]; k < power; ++k) value *= x[d];
    }
    sum += value;
  }
  return sum;
}

}  // namespace sinew::functions

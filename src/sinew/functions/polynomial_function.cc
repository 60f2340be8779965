#include <sinew/common/error.h>
#include <sinew/functions/polynomial_function.h>

namespace sinew::functions {

double PolynomialFunction::CalcDerivative(double x, int order) const {
  if (order < 0) throw Error("PolynomialFunction: negative derivative order");
  const int n = static_cast<int>(coefficients_.size());
  // Horner over the terms that survive `order` differentiations; the term of power p
  // contributes c * p (p-1) ... (p-order+1) x^(p-order).
  double result = 0.0;
  for (int i = 0; i < n - order; ++i) {
    const int power = n - 1 - i;
    double factor = 1.0;
    for (int k = 0; k < order; ++k) factor *= power - k;
    result = result * x + factor * coefficients_[i];
  }
  return result;
}

}  // namespace sinew::functions

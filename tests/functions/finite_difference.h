// Central finite differences used by the function tests as an independent check of analytic
// derivatives.
#pragma once

#include <sinew/functions/function.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace sinew::testing {

/// d/dx of f's derivative of `order` - 1 at x, by a central difference with step h.
inline double CentralDifference(const functions::Function& f, double x, int order,
                                double h = 1e-6) {
  return (f.CalcDerivative(x + h, order - 1) - f.CalcDerivative(x - h, order - 1)) / (2.0 * h);
}

/// Whether the third derivative of a piecewise cubic f (its f'' differenced across each piece's
/// middle) changes from every piece between `knots` to the next, by more than 1e-3 of itself,
/// the line before the first knot counting as 0: then every knot but the last is a breakpoint.
inline bool ThirdDerivativeChangesAtEveryKnot(const functions::Function& f,
                                              const std::vector<double>& knots) {
  double previous = 0.0;
  for (std::size_t k = 0; k + 1 < knots.size(); ++k) {
    const double mid = 0.5 * (knots[k] + knots[k + 1]);
    const double third = CentralDifference(f, mid, 3, 1e-3);
    if (!(std::abs(third - previous) > 1e-3 * std::abs(third))) return false;
    previous = third;
  }
  return true;
}

}  // namespace sinew::testing

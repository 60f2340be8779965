// Central finite differences used by the function tests as an independent check of analytic
// derivatives.
#pragma once

#include <sinew/functions/function.h>

#include <algorithm>
#include <cmath>

namespace sinew::testing {

/// d/dx of f's derivative of `order` - 1 at x, by a central difference with step h.
inline double CentralDifference(const functions::Function& f, double x, int order,
                                double h = 1e-6) {
  return (f.CalcDerivative(x + h, order - 1) - f.CalcDerivative(x - h, order - 1)) / (2.0 * h);
}

}  // namespace sinew::testing

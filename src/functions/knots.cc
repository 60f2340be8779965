#include "functions/knots.h"

#include <cmath>

#include "common/error.h"

namespace sinew {

void CheckKnots(std::span<const double> x, std::span<const double> y, int min_points,
                const std::string& type) {
  if (x.size() != y.size()) {
    throw Error(type + ": x has " + std::to_string(x.size()) + " values but y has " +
                std::to_string(y.size()));
  }
  if (static_cast<int>(x.size()) < min_points) {
    throw Error(type + ": needs at least " + std::to_string(min_points) + " points, got " +
                std::to_string(x.size()));
  }
  for (size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i]) || !std::isfinite(y[i])) {
      throw Error(type + ": point " + std::to_string(i) + " is not finite");
    }
    if (i > 0 && x[i] < x[i - 1]) {
      throw Error(type + ": x must be non-decreasing, but x[" + std::to_string(i) + "] < x[" +
                  std::to_string(i - 1) + "]");
    }
  }
}

int FindKnotInterval(std::span<const double> x, double value) {
  const int n = static_cast<int>(x.size());
  if (!(value > x[0])) return 0;  // also NaN
  if (value >= x[n - 1]) return n - 2;
  // Bisection as OpenSim's knot functions do it: stop at the first probed k with
  // x[k] <= value <= x[k+1]. Here x[0] < value < x[n-1], so k + 1 <= n - 1 always.
  int low = 0;
  int high = n;
  while (true) {
    const int k = (low + high) / 2;
    if (value < x[k]) {
      high = k;
    } else if (value > x[k + 1]) {
      low = k;
    } else {
      return k;
    }
  }
}

}  // namespace sinew

#include <sinew/common/error.h>
#include <sinew/functions/knots.h>

#include <cmath>

namespace sinew::functions {

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

}  // namespace sinew::functions

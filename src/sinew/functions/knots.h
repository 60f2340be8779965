// Helpers shared by the knot-based functions (splines, piecewise functions).
#pragma once

#include <span>
#include <string>

namespace sinew::functions {

/// Checks a knot table: x and y of equal size, at least `min_points` points, finite values and
/// x non-decreasing. Throws sinew::Error naming `type` otherwise.
void CheckKnots(std::span<const double> x, std::span<const double> y, int min_points,
                const std::string& type);

/// The index k of the knot interval [x[k], x[k+1]] holding `value` (n = x.size() >= 2):
/// values below x[0] give 0, values above x[n-1] give n-2. Inside, the bisection is OpenSim's,
/// so a value exactly on an interior knot picks the same side OpenSim picks (this matters only
/// for functions that jump or kink at knots). O(log n).
inline int FindKnotInterval(std::span<const double> x, double value) {
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

}  // namespace sinew::functions

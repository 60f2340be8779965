// Helpers shared by the knot-based functions (splines, piecewise functions).
#pragma once

#include <span>
#include <string>

namespace sinew {

/// Checks a knot table: x and y of equal size, at least `min_points` points, finite values and
/// x non-decreasing. Throws sinew::Error naming `type` otherwise.
void CheckKnots(std::span<const double> x, std::span<const double> y, int min_points,
                const std::string& type);

/// The index k of the interval [x[k], x[k+1]) holding `value`, clamped to [0, n-2]
/// (n = x.size() >= 2): values below x[0] give 0, values at or above x[n-1] give n-2.
/// Binary search, O(log n).
int FindKnotInterval(std::span<const double> x, double value);

}  // namespace sinew

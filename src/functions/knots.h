// Helpers shared by the knot-based functions (splines, piecewise functions).
#pragma once

#include <span>
#include <string>

namespace sinew {

/// Checks a knot table: x and y of equal size, at least `min_points` points, finite values and
/// x non-decreasing. Throws sinew::Error naming `type` otherwise.
void CheckKnots(std::span<const double> x, std::span<const double> y, int min_points,
                const std::string& type);

/// The index k of the knot interval [x[k], x[k+1]] holding `value` (n = x.size() >= 2):
/// values below x[0] give 0, values above x[n-1] give n-2. Inside, the bisection is OpenSim's,
/// so a value exactly on an interior knot picks the same side OpenSim picks (this matters only
/// for functions that jump or kink at knots). O(log n).
int FindKnotInterval(std::span<const double> x, double value);

}  // namespace sinew

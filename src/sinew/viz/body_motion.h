// Body poses over time: what exporters and the renderer animate.
#pragma once

#include <sinew/math/transform.h>

#include <vector>

namespace sinew::viz {

/// Poses of every body at a sequence of times. X_GB[k][b] is body b's pose in ground at
/// times[k] (s); b indexes ModelSpec::bodies (ground included, normally identity).
struct BodyMotion {
  std::vector<double> times;
  std::vector<std::vector<Transform>> X_GB;
  /// The coordinates (ModelSpec::coordinates order) the poses come from, one vector per frame,
  /// when known (motion tables and the default pose); empty otherwise. Muscle paths need them.
  std::vector<std::vector<double>> q;
};

}  // namespace sinew::viz

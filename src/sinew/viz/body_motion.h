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
};

}  // namespace sinew::viz

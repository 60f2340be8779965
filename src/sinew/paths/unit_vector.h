// The unit vector along a vector, or zero for a vector too short to have a direction, as
// OpenSim's wrapping code normalizes (WrapMath::NormalizeOrZero): its iterations and
// decisions depend on getting zero there, not NaN.
#pragma once

#include <sinew/math/types.h>

#include <limits>

namespace sinew::paths {

/// v / |v| (computed as v * (1 / |v|), as OpenSim does), or zero when |v| < machine epsilon.
inline Vec3 NormalizedOrZero(const Vec3& v) {
  const double norm = v.norm();
  return norm >= std::numeric_limits<double>::epsilon() ? Vec3(v * (1.0 / norm)) : Vec3::Zero();
}

}  // namespace sinew::paths

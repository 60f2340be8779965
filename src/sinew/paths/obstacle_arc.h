// The arc of OpenSim's obstacle-set wraps (WrapCylinderObst, WrapSphereObst; Garner and Pandy's
// obstacle-set method): in a plane through the obstacle's centre, the path leaves P along the
// tangent that turns one given way round the circle and reaches S along the tangent turning the
// same way, and it wraps only when that turn is between 0 and 180 degrees.
#pragma once

#include <sinew/math/types.h>

namespace sinew::paths {

/// The obstacles' circle is smaller than the obstacle: OpenSim's WrapCylinderObst and
/// WrapSphereObst wrap over a circle of 0.8 times their `radius`.
inline constexpr double kObstacleRadiusFraction = 0.8;

/// One obstacle arc, in the plane's 3-d coordinates.
struct ObstacleArc {
  bool point_inside = false;  ///< P or S is inside the circle: no wrap
  bool wraps = false;         ///< the turn from Q to T is in [0, 180] degrees the given way
  Vec3 q = Vec3::Zero();      ///< the tangent point from P
  Vec3 t = Vec3::Zero();      ///< the tangent point from S
  double angle = 0.0;         ///< the turn from Q to T (rad, in [0, pi])
};

/// The arc from p to s (both in the plane through the origin with unit normal n) round the
/// circle of `radius` about the origin, turning counter-clockwise about n when `turn` is +1 and
/// clockwise when -1.
ObstacleArc CalcObstacleArc(const Vec3& p, const Vec3& s, const Vec3& n, double radius, int turn);

}  // namespace sinew::paths

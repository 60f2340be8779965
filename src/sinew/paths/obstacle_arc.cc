#include <sinew/paths/obstacle_arc.h>
#include <sinew/paths/wrap_tangents.h>

#include <algorithm>
#include <cmath>

namespace sinew::paths {

ObstacleArc CalcObstacleArc(const Vec3& p, const Vec3& s, const Vec3& n, double radius, int turn) {
  ObstacleArc arc;
  if (p.squaredNorm() < radius * radius || s.squaredNorm() < radius * radius) {
    arc.point_inside = true;
    return arc;
  }
  // From P, the tangent point turned the given way from P's direction; from S, the one turned
  // back toward P, so the path runs P -> Q, round the circle the given way, T -> S.
  const CircleTangents from_p = CalcCircleTangents(p, n, radius);
  const CircleTangents from_s = CalcCircleTangents(s, n, radius);
  arc.q = turn > 0 ? from_p.plus : from_p.minus;
  arc.t = turn > 0 ? from_s.minus : from_s.plus;
  // OpenSim's 180-degree rule: no contact when the turn from Q to T goes the other way.
  if (turn * n.dot(arc.q.cross(arc.t)) < 0.0) return arc;
  arc.wraps = true;
  // OpenSim's angle from the chord: acos(1 - |Q - T|^2 / (2 r^2)), in [0, pi].
  const double chord_squared = (arc.q - arc.t).squaredNorm();
  arc.angle = std::acos(std::clamp(1.0 - 0.5 * chord_squared / (radius * radius), -1.0, 1.0));
  return arc;
}

}  // namespace sinew::paths

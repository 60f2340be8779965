// Independent references for the wrap surface tests: closed-form lengths of shortest paths
// over a circle and an unrolled cylinder, and helpers to measure a wrapped path.
#pragma once

#include <sinew/paths/wrap_surface.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

namespace sinew::paths::testing {

/// P-T1 + arc + T2-S, or |P - S| when the segment is not wrapped.
inline double PathLength(const Vec3& p_WP, const Vec3& p_WS, const WrapResult& result) {
  if (!result.wrapped) return (p_WS - p_WP).norm();
  return (result.p_WT1 - p_WP).norm() + result.arc_length + (p_WS - result.p_WT2).norm();
}

/// The shortest path from P around a circle of `radius` (centred at the origin, in the plane of
/// P, S and the origin) to S, going round the side the segment P-S passes (or the other side
/// when `other_side`): the two tangent lengths sqrt(d^2 - r^2) plus r times the angle between P
/// and S less the angles acos(r/d) the tangent lines take.
inline double CircleWrapLength(const Vec3& p, const Vec3& s, double radius, bool other_side) {
  const double dp = p.norm();
  const double ds = s.norm();
  const double between = std::acos(std::clamp(p.dot(s) / (dp * ds), -1.0, 1.0));
  const double around = other_side ? 2.0 * std::numbers::pi - between : between;
  return std::sqrt(dp * dp - radius * radius) + std::sqrt(ds * ds - radius * radius) +
         radius * (around - std::acos(radius / dp) - std::acos(radius / ds));
}

/// The shortest path from P over the infinite cylinder of `radius` about z to S, unrolled: a
/// straight line whose run round the cylinder is the circle wrap of the cross-section (the
/// short way) and whose rise is the height from P to S.
inline double CylinderGeodesicLength(const Vec3& p, const Vec3& s, double radius) {
  const Vec3 p_xy(p.x(), p.y(), 0.0);
  const Vec3 s_xy(s.x(), s.y(), 0.0);
  return std::hypot(CircleWrapLength(p_xy, s_xy, radius, false), s.z() - p.z());
}

/// A point uniformly distributed in the box [-half, half]^3.
inline Vec3 RandomPoint(std::mt19937& random, double half) {
  std::uniform_real_distribution<double> coordinate(-half, half);
  return {coordinate(random), coordinate(random), coordinate(random)};
}

/// `count` pairs (P, S) of random points in [-half, half]^3, from a fixed seed so every run sees
/// the same, that `keep(p, s)` accepts; with `same_height` S is moved to P's z first.
template <typename Keep>
std::vector<std::pair<Vec3, Vec3>> RandomPairs(int count, double half, unsigned seed,
                                               bool same_height, Keep keep) {
  std::mt19937 random(seed);
  std::vector<std::pair<Vec3, Vec3>> pairs;
  while (static_cast<int>(pairs.size()) < count) {
    const Vec3 p = RandomPoint(random, half);
    Vec3 s = RandomPoint(random, half);
    if (same_height) s.z() = p.z();
    if (keep(p, s)) pairs.emplace_back(p, s);
  }
  return pairs;
}

}  // namespace sinew::paths::testing

// Tangent points shared by the round wrap surfaces (sphere, cylinder): the two points where a
// line from an outside point touches a circle, and OpenSim's choice of one on each side.
#pragma once

#include <sinew/math/types.h>

namespace sinew::paths {

/// The two points where lines from `p` touch the circle of radius `radius` centred at the
/// origin in the plane through the origin with unit normal `n` (p in that plane, |p| > radius):
/// T = (radius^2 / |p|^2) p +- (radius sqrt(|p|^2 - radius^2) / |p|) (n x p/|p|). `plus` takes
/// the + sign (counter-clockwise about n from p's direction), `minus` the - sign.
struct CircleTangents {
  Vec3 plus;
  Vec3 minus;
};
CircleTangents CalcCircleTangents(const Vec3& p, const Vec3& n, double radius);

/// One tangent point on each side of the surface: T1 (from P) and T2 (from S).
struct TangentPair {
  Vec3 t1;
  Vec3 t2;
};

/// OpenSim's choice when no quadrant constrains the side: of the four pairs, the one whose
/// directions from the centre (`c1` for T1's candidates, `c2` for T2's) make the smallest angle,
/// i.e. the shorter way around. On equal angles the later pair in the order (plus, plus),
/// (plus, minus), (minus, plus), (minus, minus) is kept, as OpenSim does.
TangentPair ChooseClosestPair(const CircleTangents& from_p, const Vec3& c1,
                              const CircleTangents& from_s, const Vec3& c2);

}  // namespace sinew::paths

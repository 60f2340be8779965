#include <sinew/paths/wrap_tangents.h>

#include <array>
#include <cmath>

namespace sinew::paths {

CircleTangents CalcCircleTangents(const Vec3& p, const Vec3& n, double radius) {
  const double distance = p.norm();
  const Vec3 p_unit = p / distance;
  const Vec3 along = (radius * radius / distance) * p_unit;
  const double half_chord =
      radius * std::sqrt(std::max(0.0, distance * distance - radius * radius)) / distance;
  const Vec3 across = half_chord * n.cross(p_unit);
  return {along + across, along - across};
}

TangentPair ChooseClosestPair(const CircleTangents& from_p, const Vec3& c1,
                              const CircleTangents& from_s, const Vec3& c2) {
  const std::array<TangentPair, 4> pairs{{{from_p.plus, from_s.plus},
                                          {from_p.plus, from_s.minus},
                                          {from_p.minus, from_s.plus},
                                          {from_p.minus, from_s.minus}}};
  int best = 0;
  double best_cosine = -2.0;
  for (int i = 0; i < 4; ++i) {
    const double cosine = (pairs[i].t1 - c1).normalized().dot((pairs[i].t2 - c2).normalized());
    if (cosine >= best_cosine) {
      best = i;
      best_cosine = cosine;
    }
  }
  return pairs[best];
}

}  // namespace sinew::paths

#include <sinew/common/error.h>
#include <sinew/paths/wrap_sphere.h>
#include <sinew/paths/wrap_tangents.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sinew::paths {
namespace {

// Below this |unit(P - S) x unit(S)| the line P-S passes (almost) through the centre and the
// plane of P, S and the centre is undefined; OpenSim uses the same threshold.
constexpr double kThroughCentre = 1e-5;
// Spacing of the arc points returned for drawing (m), and their largest number.
constexpr double kArcPointSpacing = 0.002;
constexpr int kMaxArcSegments = 100;

// True when the segment from P to S enters the sphere (both crossings strictly inside it).
bool SegmentCrossesSphere(const Vec3& p_WP, const Vec3& p_WS, double radius) {
  const Vec3 d = p_WS - p_WP;
  const double a = d.squaredNorm();
  const double b = 2.0 * p_WP.dot(d);
  const double c = p_WP.squaredNorm() - radius * radius;
  const double discriminant = b * b - 4.0 * a * c;
  if (a <= 0.0 || discriminant < 0.0) return false;
  const double root = std::sqrt(discriminant);
  const double t_in = (-b - root) / (2.0 * a);
  const double t_out = (-b + root) / (2.0 * a);
  return t_in > 0.0 && t_in < 1.0 && t_out > 0.0 && t_out < 1.0;
}

// True when the line P-S passes (within OpenSim's threshold) through the centre, so the plane
// of P, S and the centre is undefined.
bool PassesThroughCentre(const Vec3& p_WP, const Vec3& p_WS) {
  return (p_WP - p_WS).normalized().cross(p_WS.normalized()).norm() < kThroughCentre;
}

// The unit normal of the plane through P, S and the centre. Through the centre, every plane
// holding the line gives the same length; OpenSim then reuses the previous evaluation's tangent
// points (state a const surface does not have), so Sinew takes the plane that also holds the
// quadrant's axis, or W's axis most perpendicular to the line when unconstrained.
Vec3 WrapPlaneNormal(const Vec3& p_WP, const Vec3& p_WS, const WrapQuadrant& quadrant) {
  const Vec3 line = (p_WP - p_WS).normalized();
  if (!PassesThroughCentre(p_WP, p_WS)) return line.cross(p_WS.normalized()).normalized();
  Vec3 side = quadrant.constrained() ? quadrant.ActiveDirection() : Vec3::Zero();
  if (!quadrant.constrained() || line.cross(side).norm() < kThroughCentre) {
    Eigen::Index axis = 0;
    line.cwiseAbs().minCoeff(&axis);
    side = Vec3::Unit(axis);
  }
  return line.cross(side).normalized();
}

// OpenSim's choice of side under a quadrant when P and S are not both on the active side: the
// tangent point of each pair facing the direction from P and S to the centre, swapped to the
// other pair when the path would then leave the active direction.
TangentPair ChooseActiveSidePair(const CircleTangents& from_p, const CircleTangents& from_s,
                                 const Vec3& p_WP, const Vec3& p_WS, const WrapQuadrant& quadrant) {
  const Vec3 toward_centre = (-p_WP - p_WS).normalized();
  const bool p_plus =
      from_p.plus.normalized().dot(toward_centre) > from_p.minus.normalized().dot(toward_centre);
  const bool s_plus =
      from_s.plus.normalized().dot(toward_centre) > from_s.minus.normalized().dot(toward_centre);
  TangentPair pair{p_plus ? from_p.plus : from_p.minus, s_plus ? from_s.plus : from_s.minus};
  const Vec3 path_direction = (pair.t1 - p_WP) + (pair.t2 - p_WS);
  if (path_direction.dot(quadrant.ActiveDirection()) < 0.0) {
    pair = {p_plus ? from_p.minus : from_p.plus, s_plus ? from_s.minus : from_s.plus};
  }
  return pair;
}

// Points along the arc of the circle about `axis` (through the centre) from T1, turning by
// `angle` (rad, signed), for drawing.
std::vector<Vec3> SampleArc(const Vec3& p_WT1, const Vec3& axis, double angle, double length) {
  const int segments =
      std::clamp(static_cast<int>(std::ceil(length / kArcPointSpacing)), 1, kMaxArcSegments);
  std::vector<Vec3> points;
  points.reserve(segments + 1);
  for (int i = 0; i <= segments; ++i) {
    points.push_back(Eigen::AngleAxisd(angle * i / segments, axis) * p_WT1);
  }
  return points;
}

}  // namespace

WrapSphere::WrapSphere(double radius, WrapQuadrant quadrant)
    : radius_(radius), quadrant_(quadrant) {
  if (!(radius > 0.0) || !std::isfinite(radius)) {
    throw Error("WrapSphere: the radius must be positive and finite");
  }
}

WrapResult WrapSphere::Wrap(const Vec3& p_WP, const Vec3& p_WS, const WrapOptions& options) const {
  WrapResult result;
  // A point inside the sphere, or a segment that does not enter it: the path stays straight.
  if (p_WP.norm() < radius_ || p_WS.norm() < radius_) {
    result.point_inside = true;
    return result;
  }
  if (!SegmentCrossesSphere(p_WP, p_WS, radius_)) return result;

  const Vec3 n = WrapPlaneNormal(p_WP, p_WS, quadrant_);
  const CircleTangents from_p = CalcCircleTangents(p_WP, n, radius_);
  const CircleTangents from_s = CalcCircleTangents(p_WS, n, radius_);
  TangentPair pair = ChooseClosestPair(from_p, Vec3::Zero(), from_s, Vec3::Zero());
  bool long_way = false;
  if (quadrant_.constrained() && PassesThroughCentre(p_WP, p_WS)) {
    // OpenSim skips its quadrant rules here (it jumps to the path with its previous tangent
    // points, a plain wrap); Sinew keeps the tangent points facing the active side.
    const Vec3 active = quadrant_.ActiveDirection();
    pair = {from_p.plus.dot(active) >= from_p.minus.dot(active) ? from_p.plus : from_p.minus,
            from_s.plus.dot(active) >= from_s.minus.dot(active) ? from_s.plus : from_s.minus};
  } else if (quadrant_.constrained()) {
    const bool p_active = quadrant_.OnActiveSide(p_WP);
    const bool s_active = quadrant_.OnActiveSide(p_WS);
    if (p_active || s_active) {
      // The segment crosses the sphere (checked above), so this wrap is mandatory.
      result.mandatory = true;
    }
    if (!p_active || !s_active) {
      pair = ChooseActiveSidePair(from_p, from_s, p_WP, p_WS, quadrant_);
      // The chosen points face away from where the path comes from: it goes the long way.
      long_way = (pair.t1 + pair.t2).dot((pair.t1 - p_WP) + (pair.t2 - p_WS)) < 0.0;
    }
  }

  // The signed angle from T1 to T2 about n; the long way round turns the other way.
  const double short_angle = std::atan2(pair.t1.cross(pair.t2).dot(n), pair.t1.dot(pair.t2));
  const double angle =
      long_way ? -std::copysign(2.0 * std::numbers::pi - std::abs(short_angle), short_angle)
               : short_angle;
  result.wrapped = true;
  result.p_WT1 = pair.t1;
  result.p_WT2 = pair.t2;
  result.arc_length = radius_ * std::abs(angle);
  if (options.with_arc_points) result.arc_points = SampleArc(pair.t1, n, angle, result.arc_length);
  return result;
}

}  // namespace sinew::paths

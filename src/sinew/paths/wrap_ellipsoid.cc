#include <sinew/common/error.h>
#include <sinew/paths/ellipsoid_closest_point.h>
#include <sinew/paths/ellipsoid_tangent_point.h>
#include <sinew/paths/unit_vector.h>
#include <sinew/paths/wrap_ellipsoid.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace sinew::paths {
namespace {

// OpenSim's constants (WrapEllipsoid.cpp). A point this far inside (in sum (x/a)^2 - 1) is
// inside; P and S this close in direction from the centre (1 - cos) do not wrap.
constexpr double kInside = 1e-4;
constexpr double kSameDirection = 1e-4;
// Hybrid method: at or below this |cosine| between the segment and its most parallel axis the
// plane point is the fan's alone, above kAxialOnly the axial one's alone, blended between.
constexpr double kFanOnly = 0.7073;
constexpr double kAxialOnly = 0.9;
// The fan samples the chord at this many intervals; the axial point fades out within this
// fraction of the chord's ends.
constexpr int kFanSamples = 300;
constexpr double kChordEndBlend = 0.3;
// The arc is a polyline of chords this long (m; OpenSim assumes metres), at most kMaxChords.
constexpr double kChordLength = 0.001;
constexpr int kMaxChords = 499;

// The surface point c1 that, with P and S, spans the wrap plane, for OpenSim's `method`; all in
// scaled coordinates. r1 and r2 are where the segment enters and leaves the ellipsoid.
struct PlanePoint {
  Vec3 c1 = Vec3::Zero();
  // How much of c1 came from the fan (-infinity when none: OpenSim's sentinel).
  double fan_weight = -std::numeric_limits<double>::infinity();
  // Whether the tangent-point search starts at c1 (else at the entry and exit points).
  bool start_at_c1 = true;
};

PlanePoint ChoosePlanePoint(const Vec3& a, const Vec3& p1p2, const Vec3& r1, const Vec3& r2,
                            WrapOptions::Method method) {
  PlanePoint out;
  const Vec3 r1r2 = r2 - r1;
  if (method == WrapOptions::Method::kMidpoint) {
    out.c1 = CalcClosestPointOnEllipsoid(a, r1 + 0.5 * r1r2, -1, out.c1);
    return out;
  }
  // Axial: where the chord crosses the principal plane normal to the axis most parallel to
  // it, and the surface point nearest that (solved in that plane's ellipse).
  const Vec3 mu = NormalizedOrZero(p1p2).cwiseAbs();
  int best = 0;
  for (int i = 1; i < 3; ++i) {
    if (mu[i] > mu[best]) best = i;
  }
  const double t = -r1[best] / r1r2[best];
  const Vec3 axial_c1 = CalcClosestPointOnEllipsoid(a, r1 + t * r1r2, best, Vec3::Zero());
  double mu_best = mu[best];
  if (method == WrapOptions::Method::kHybrid && mu_best > kFanOnly) {
    // An axial point near or beyond the chord's ends fades toward the fan.
    double s = 1.0;
    if (t < 0.0 || t > 1.0) {
      s = 0.0;
    } else if (t < kChordEndBlend) {
      s = t / kChordEndBlend;
    } else if (t > 1.0 - kChordEndBlend) {
      s = (1.0 - t) / kChordEndBlend;
    }
    if (s < 1.0) mu_best = kFanOnly + s * (mu_best - kFanOnly);
  }
  if (method == WrapOptions::Method::kAxial || mu_best > kFanOnly) out.c1 = axial_c1;
  if (method == WrapOptions::Method::kAxial) {
    out.start_at_c1 = t > 0.0 && t < 1.0;
    return out;
  }
  if (mu_best >= kAxialOnly) return out;
  // Fan: the mean direction from points along the chord to their nearest surface points, from
  // the chord's middle.
  Vec3 sum = Vec3::Zero();
  Vec3 nearest = axial_c1;
  for (int i = 1; i < kFanSamples - 1; ++i) {
    const Vec3 sample = r1 + (static_cast<double>(i) / kFanSamples) * r1r2;
    nearest = CalcClosestPointOnEllipsoid(a, sample, -1, nearest);
    sum += NormalizedOrZero(nearest - sample);
  }
  const Vec3 fan_point = r1 + 0.5 * r1r2 + NormalizedOrZero(sum);
  if (mu_best <= kFanOnly) {
    out.c1 = CalcClosestPointOnEllipsoid(a, fan_point, -1, out.c1);
    out.fan_weight = 1.0;
    return out;
  }
  const double axial_weight = (mu_best - kFanOnly) / (kAxialOnly - kFanOnly);
  const Vec3 fan_c1 = CalcClosestPointOnEllipsoid(a, fan_point, -1, out.c1);
  out.c1 = CalcClosestPointOnEllipsoid(a, axial_weight * out.c1 + (1.0 - axial_weight) * fan_c1, -1,
                                       out.c1);
  out.fan_weight = 1.0 - axial_weight;
  return out;
}

// OpenSim's path over the ellipsoid from r1 to r2 in the plane n . x + d = 0 (scaled
// coordinates; `factor` scales metres to them): a polyline of about 1 mm chords whose interior
// points are where rays from a0 (the plane's point on the axis most normal to it) at evenly
// turned angles leave the ellipsoid. The short way from r1 to r2, or the long way. Only the
// length and the points next to the ends are kept (no heap use); `points`, when given, gets
// them all.
struct Arc {
  double length = 0.0;
  int num_points = 2;                                      ///< r1, the interior points, r2
  Vec3 after_r1 = Vec3::Zero(), before_r2 = Vec3::Zero();  ///< second and second-to-last
};

Arc CalcArc(const Vec3& r1, const Vec3& r2, const Vec3& a, const Vec3& n, double d, bool long_way,
            double factor, std::vector<Vec3>* points) {
  Arc arc;
  arc.after_r1 = r2;
  arc.before_r2 = r1;
  if (points) *points = {r1};
  const double chord = (r1 - r2).norm() / factor;
  if (chord < kChordLength) {
    arc.length = (r1 - r2).norm();
    if (points) points->push_back(r2);
    return arc;
  }
  const int segments = std::min(static_cast<int>(chord / kChordLength), kMaxChords);
  int axis = 0;
  for (int i = 1; i < 3; ++i) {
    if (std::abs(n[i]) > std::abs(n[axis])) axis = i;
  }
  const Vec3 a0 = (-d / n[axis]) * Vec3::Unit(axis);
  const Vec3 u1 = NormalizedOrZero(r1 - a0);
  const Vec3 u2 = NormalizedOrZero(r2 - a0);
  // OpenSim takes acos of the unclamped cosine (NaN when rounding pushes it past 1).
  const double angle = std::acos(std::clamp(u1.dot(u2), -1.0, 1.0));
  const double step = long_way ? -(2.0 * std::numbers::pi - angle) / segments : angle / segments;
  const Vec3 normal = NormalizedOrZero(u1.cross(u2));
  const Vec3 across = normal.cross(u1);
  const Vec3 a0_scaled = a0.cwiseQuotient(a);
  if (points) points->reserve(static_cast<size_t>(segments) + 1);
  Vec3 previous = r1;
  for (int i = 1; i < segments; ++i) {
    const double phi = i * step;
    const Vec3 ray = std::cos(phi) * u1 + std::sin(phi) * across;
    // a0 + s ray on the ellipsoid, the far root.
    const Vec3 ray_scaled = ray.cwiseQuotient(a);
    const double qa = ray_scaled.squaredNorm();
    const double qb = 2.0 * ray_scaled.dot(a0_scaled);
    const double qc = a0_scaled.squaredNorm() - 1.0;
    const double s = (-qb + std::sqrt(qb * qb - 4.0 * qa * qc)) / (2.0 * qa);
    const Vec3 point = a0 + s * ray;
    if (i == 1) arc.after_r1 = point;
    arc.before_r2 = point;
    arc.length += (point - previous).norm();
    if (points) points->push_back(point);
    previous = point;
  }
  arc.length += (r2 - previous).norm();
  arc.num_points = segments + 1;
  if (points) points->push_back(r2);
  return arc;
}

}  // namespace

WrapEllipsoid::WrapEllipsoid(const Vec3& radii, WrapQuadrant quadrant)
    : radii_(radii), quadrant_(quadrant) {
  if (!(radii.minCoeff() > 0.0) || !radii.allFinite()) {
    throw Error("WrapEllipsoid: the radii must be positive and finite");
  }
}

WrapResult WrapEllipsoid::Wrap(const Vec3& p_WP, const Vec3& p_WS,
                               const WrapOptions& options) const {
  WrapResult result;
  // OpenSim scales the problem so that the semi-axes average 1 (its iterations' tolerances
  // are in these units).
  const double factor = 3.0 / radii_.sum();
  const Vec3 p1 = factor * p_WP, p2 = factor * p_WS, a = factor * radii_;
  const double p1_level = p1.cwiseQuotient(a).squaredNorm() - 1.0;
  const double p2_level = p2.cwiseQuotient(a).squaredNorm() - 1.0;
  if (p1_level < -kInside || p2_level < -kInside) {
    result.point_inside = true;
    return result;
  }
  if (std::abs(NormalizedOrZero(p1).dot(NormalizedOrZero(p2)) - 1.0) < kSameDirection) {
    return result;
  }
  // Where the line P-S meets the ellipsoid (x = p2 + l (p1 - p2)): both crossings strictly
  // between P and S, or no wrap.
  const Vec3 p1p2 = p1 - p2;
  const Vec3 f1 = p1p2.cwiseQuotient(a), f2 = p2.cwiseQuotient(a);
  const double qa = f1.squaredNorm(), qb = 2.0 * f1.dot(f2), qc = f2.squaredNorm() - 1.0;
  const double discriminant = qb * qb - 4.0 * qa * qc;
  if (discriminant < 0.0) return result;
  const double l1 = (-qb + std::sqrt(discriminant)) / (2.0 * qa);
  const double l2 = (-qb - std::sqrt(discriminant)) / (2.0 * qa);
  if (!(0.0 < l1 && l1 < 1.0) || !(0.0 < l2 && l2 < 1.0)) return result;
  Vec3 r1 = p2 + l1 * p1p2, r2 = p2 + l2 * p1p2;

  PlanePoint plane = ChoosePlanePoint(a, p1p2, r1, r2, options.method);
  if (plane.start_at_c1) r1 = r2 = plane.c1;
  // Under a quadrant, a plane point on the inactive side is mirrored to the active one and,
  // as far as the fan decided it, drawn toward the dividing plane and back onto the surface.
  if (quadrant_.constrained() && quadrant_.SideOf(plane.c1) != quadrant_.sign) {
    const int axis = quadrant_.axis;
    const double before = plane.c1[axis];
    plane.c1[axis] = -plane.c1[axis];
    r1 = r2 = plane.c1;
    const double fan_weight = std::min(plane.fan_weight, 1.0);
    if (fan_weight > 0.0) {
      const double middle = 0.5 * (before + plane.c1[axis]);
      plane.c1[axis] += fan_weight * (middle - plane.c1[axis]);
      plane.c1 = CalcClosestPointOnEllipsoid(a, plane.c1, -1, plane.c1);
    }
  }
  // The wrap plane through P, S and c1: n . x + d = 0.
  const Vec3 n = NormalizedOrZero(p1p2.cross(p1 - plane.c1));
  const double d = -n.dot(plane.c1);
  SolveEllipsoidTangentPoint(a, p1, p1_level, n, d, r1);
  SolveEllipsoidTangentPoint(a, p2, p2_level, n, d, r2);

  std::vector<Vec3>* points = options.with_arc_points ? &result.arc_points : nullptr;
  Arc arc = CalcArc(r1, r2, a, n, d, false, factor, points);
  // Under a quadrant, a path whose first or last chord turns back toward P or S goes the long
  // way round instead.
  if (quadrant_.constrained() && arc.num_points > 2) {
    if (NormalizedOrZero(p1 - r1).dot(NormalizedOrZero(arc.after_r1 - r1)) > 0.0 ||
        NormalizedOrZero(p2 - r2).dot(NormalizedOrZero(arc.before_r2 - r2)) > 0.0) {
      arc = CalcArc(r1, r2, a, n, d, true, factor, points);
    }
  }
  result.wrapped = true;
  result.mandatory = true;
  result.p_WT1 = r1 / factor;
  result.p_WT2 = r2 / factor;
  result.arc_length = arc.length / factor;
  for (Vec3& point : result.arc_points) point /= factor;
  return result;
}

}  // namespace sinew::paths

#include <sinew/common/error.h>
#include <sinew/paths/obstacle_arc.h>
#include <sinew/paths/wrap_sphere_obst.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sinew::paths {
namespace {

// OpenSim's test for P and S in line with the centre: |P x S| at most this (m^2).
constexpr double kInLineCross = 1e-7;
// Arc points for drawing: one every 5 degrees.
constexpr double kArcPointStep = 5.0 * std::numbers::pi / 180.0;

}  // namespace

WrapSphereObst::WrapSphereObst(double radius) : radius_(radius) {
  if (!(radius > 0.0) || !std::isfinite(radius)) {
    throw Error("WrapSphereObst: the radius must be positive and finite");
  }
}

WrapResult WrapSphereObst::Wrap(const Vec3& p_WP, const Vec3& p_WS,
                                const WrapOptions& options) const {
  WrapResult result;
  const Vec3 normal = p_WP.cross(p_WS);
  if (normal.norm() <= kInLineCross) {
    result.point_inside = true;
    return result;
  }
  // In the plane of P, S and the centre, S is counter-clockwise from P about P x S.
  const double r = kObstacleRadiusFraction * radius_;
  const Vec3 n = normal.normalized();
  const ObstacleArc arc = CalcObstacleArc(p_WP, p_WS, n, r, +1);
  result.point_inside = arc.point_inside;
  if (!arc.wraps) return result;
  result.wrapped = true;
  result.p_WT1 = arc.q;
  result.p_WT2 = arc.t;
  result.arc_length = r * arc.angle;
  if (!options.with_arc_points) return result;
  const int steps = 1 + static_cast<int>(arc.angle / kArcPointStep);
  for (int i = 0; i <= steps; ++i) {
    const double angle = arc.angle * static_cast<double>(i) / steps;
    result.arc_points.push_back(Eigen::AngleAxisd(angle, n) * arc.q);
  }
  return result;
}

}  // namespace sinew::paths

#include <sinew/common/error.h>
#include <sinew/paths/obstacle_arc.h>
#include <sinew/paths/wrap_cylinder_obst.h>

#include <cmath>
#include <numbers>

namespace sinew::paths {
namespace {

// Arc points for drawing: one every 5 degrees, as OpenSim draws it.
constexpr double kArcPointStep = 5.0 * std::numbers::pi / 180.0;

Vec3 Radial(const Vec3& p_W) { return {p_W.x(), p_W.y(), 0.0}; }

}  // namespace

WrapCylinderObst::WrapCylinderObst(double radius, Direction direction)
    : radius_(radius), direction_(direction) {
  if (!(radius > 0.0) || !std::isfinite(radius)) {
    throw Error("WrapCylinderObst: the radius must be positive and finite");
  }
}

WrapResult WrapCylinderObst::Wrap(const Vec3& p_WP, const Vec3& p_WS,
                                  const WrapOptions& options) const {
  const double r = kObstacleRadiusFraction * radius_;
  const int turn = direction_ == Direction::kRightHand ? 1 : -1;
  const ObstacleArc arc = CalcObstacleArc(Radial(p_WP), Radial(p_WS), Vec3::UnitZ(), r, turn);
  WrapResult result;
  result.point_inside = arc.point_inside;
  if (!arc.wraps) return result;
  // Heights where the unrolled path, a straight line, meets Q's and T's generators.
  const double pq = (arc.q - Radial(p_WP)).norm();
  const double ts = (Radial(p_WS) - arc.t).norm();
  const double qt = r * arc.angle;
  const double unrolled = pq + qt + ts;
  const double rise = p_WS.z() - p_WP.z();
  const double z_q = unrolled > 0.0 ? p_WP.z() + rise * pq / unrolled : p_WP.z();
  const double z_t = unrolled > 0.0 ? p_WS.z() - rise * ts / unrolled : p_WS.z();
  result.wrapped = true;
  result.p_WT1 = arc.q + z_q * Vec3::UnitZ();
  result.p_WT2 = arc.t + z_t * Vec3::UnitZ();
  result.arc_length = qt;
  if (!options.with_arc_points) return result;
  const int steps = 1 + static_cast<int>(arc.angle / kArcPointStep);
  for (int i = 0; i <= steps; ++i) {
    const double fraction = static_cast<double>(i) / steps;
    const Eigen::AngleAxisd turned(turn * fraction * arc.angle, Vec3::UnitZ());
    result.arc_points.push_back(turned * arc.q + (z_q + fraction * (z_t - z_q)) * Vec3::UnitZ());
  }
  return result;
}

}  // namespace sinew::paths

#include <sinew/viz/rasterizer.h>
#include <sinew/viz/view_hints.h>

#include <algorithm>
#include <limits>

namespace sinew::viz {

std::pair<Vec3, Vec3> FirstPoseBounds(const VisualScene& scene, const BodyMotion& motion) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  if (motion.X_GB.empty()) return {Vec3::Zero(), Vec3::Zero()};
  const std::vector<Transform>& X_GB = motion.X_GB[0];
  for (size_t b = 1; b < X_GB.size(); ++b) {
    lo = lo.cwiseMin(X_GB[b].p);
    hi = hi.cwiseMax(X_GB[b].p);
  }
  const bool has_parts = std::any_of(scene.bodies.begin(), scene.bodies.end(), [](const auto& b) {
    return b.body != model::kGroundIndex && !b.parts.empty();
  });
  if (has_parts) {
    const auto [part_lo, part_hi] = SceneBounds(scene, X_GB, false);
    lo = lo.cwiseMin(part_lo);
    hi = hi.cwiseMax(part_hi);
  }
  if (!(lo.x() <= hi.x())) return {Vec3::Zero(), Vec3::Zero()};  // ground alone
  return {lo, hi};
}

FloorPlane ViewFloor(const model::ModelSpec& spec, const VisualScene& scene,
                     const BodyMotion& motion) {
  return FloorUnder(ModelFloor(spec), FirstPoseBounds(scene, motion));
}

ViewHints MakeViewHints(const model::ModelSpec& spec, const VisualScene& scene,
                        const BodyMotion& motion, const FloorPlane& floor) {
  ViewHints hints;
  hints.floor = floor;
  const auto [lo, hi] = FirstPoseBounds(scene, motion);
  const double size = (hi - lo).norm();
  // The footprint on the floor, in two directions u, w of the plane.
  const Vec3 u = floor.normal.unitOrthogonal(), w = floor.normal.cross(u);
  double u_lo = std::numeric_limits<double>::infinity(), u_hi = -u_lo, w_lo = u_lo, w_hi = -u_lo;
  auto add = [&](const Vec3& p) {
    const Vec3 d = p - floor.point;
    u_lo = std::min(u_lo, d.dot(u)), u_hi = std::max(u_hi, d.dot(u));
    w_lo = std::min(w_lo, d.dot(w)), w_hi = std::max(w_hi, d.dot(w));
  };
  for (int corner = 0; corner < 8; ++corner) {
    add(Vec3(corner & 1 ? hi.x() : lo.x(), corner & 2 ? hi.y() : lo.y(),
             corner & 4 ? hi.z() : lo.z()));
  }
  for (const std::vector<Transform>& frame : motion.X_GB) {
    for (size_t b = 1; b < frame.size(); ++b) add(frame[b].p);
  }
  hints.grid_center = floor.point + u * (0.5 * (u_lo + u_hi)) + w * (0.5 * (w_lo + w_hi));
  hints.grid_size = std::max({2.0, 2 * size, std::max(u_hi - u_lo, w_hi - w_lo) + size});
  // The first body that moves farther than the model's size.
  for (size_t b = 1; b < spec.bodies.size() && hints.follow_body == model::kNone; ++b) {
    for (const std::vector<Transform>& frame : motion.X_GB) {
      if (b < frame.size() && (frame[b].p - motion.X_GB[0][b].p).norm() > size) {
        hints.follow_body = static_cast<int>(b);
        break;
      }
    }
  }
  return hints;
}

}  // namespace sinew::viz

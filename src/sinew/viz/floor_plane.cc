#include <sinew/viz/floor_plane.h>

#include <algorithm>

namespace sinew::viz {

FloorPlane HorizontalFloor(double height, std::string source) {
  FloorPlane floor;
  floor.point = Vec3(0, height, 0);
  floor.source = std::move(source);
  return floor;
}

FloorPlane ModelFloor(const model::ModelSpec& spec) {
  FloorPlane best;
  double best_up = 0;  // a half-space must point up at all to be a floor
  for (const model::ContactGeometrySpec& g : spec.contact_geometry) {
    if (g.type != "ContactHalfSpace" || g.body != model::kGroundIndex) continue;
    // The solid is x > 0 of the half-space's frame C: its outward normal is -x of C.
    const Vec3 normal = -g.X_BC.R.col(0).normalized();
    if (normal.y() <= best_up + 1e-12) continue;
    best_up = normal.y();
    best.point = g.X_BC.p;
    best.normal = normal;
    best.source = "ContactHalfSpace " + g.name;
  }
  return best;
}

FloorPlane FloorUnder(const FloorPlane& floor, const std::pair<Vec3, Vec3>& bounds) {
  const auto& [lo, hi] = bounds;
  if (floor.source != "y = 0" || !(lo.x() <= hi.x())) return floor;
  const double size = (hi - lo).norm();
  if (lo.y() >= floor.point.y() - 0.1 * size) return floor;
  return HorizontalFloor(lo.y(), "lowest point");
}

}  // namespace sinew::viz

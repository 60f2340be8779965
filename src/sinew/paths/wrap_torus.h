// OpenSim's WrapTorus: a torus about the z axis of its frame W, centred at W's origin, whose
// tube (radius `inner_radius`) runs round the ring circle of radius `outer_radius` in W's x-y
// plane. OpenSim wraps a segment over a cylinder of the tube's radius laid tangent to the ring
// at the ring point nearest the segment, active on the side facing the torus's axis: the path
// is kept on the hole side of the tube (docs/wrapping.md).
#pragma once

#include <sinew/paths/wrap_cylinder.h>
#include <sinew/paths/wrap_quadrant.h>
#include <sinew/paths/wrap_surface.h>

#include <optional>

namespace sinew::paths {

/// OpenSim's choice of the ring point a segment P-S is wrapped at (its `findClosestPoint`):
/// from each end, the point of the line P-S where OpenSim's residual vanishes (see
/// docs/wrapping.md: the stationary point of the distance to a circle of twice the ring radius),
/// projected radially onto the ring circle (radius `ring_radius`, about W's z axis). Of the two,
/// the one nearer the ring, or under a quadrant the one on its active side (the nearer if both
/// are). Empty when a quadrant excludes both, or the line meets W's z axis there.
std::optional<Vec3> FindTorusRingPoint(const Vec3& p_WP, const Vec3& p_WS, double ring_radius,
                                       const WrapQuadrant& quadrant);

/// Wraps a segment over a torus as OpenSim does: at the ring point c of FindTorusRingPoint, a
/// WrapCylinder of the tube's radius, 10 km long, with quadrant +x, whose x axis points from c
/// toward the torus's axis, y is -z of W and z is along the ring's tangent. The result is the
/// cylinder's (same tangent points, helix, refinement), never mandatory and never "point
/// inside", as OpenSim's WrapTorus reports every wrap as a plain one.
class WrapTorus final : public WrapSurface {
 public:
  /// 0 < `inner_radius` < `outer_radius` (m), both finite; throws sinew::Error otherwise.
  WrapTorus(double inner_radius, double outer_radius, WrapQuadrant quadrant);

  WrapResult Wrap(const Vec3& p_WP, const Vec3& p_WS, const WrapOptions& options) const override;

  double inner_radius() const { return inner_radius_; }
  double outer_radius() const { return outer_radius_; }

 private:
  double inner_radius_;
  double outer_radius_;
  WrapQuadrant quadrant_;
  WrapCylinder tube_;
};

}  // namespace sinew::paths

// OpenSim's WrapEllipsoid: an ellipsoid centred at the origin of its frame W with semi-axes
// `radii` along W's x, y and z.
#pragma once

#include <sinew/paths/wrap_quadrant.h>
#include <sinew/paths/wrap_surface.h>

namespace sinew::paths {

/// Wraps a segment over an ellipsoid as OpenSim does (docs/wrapping.md): the wrap engages when
/// the segment P-S passes through the ellipsoid (always a mandatory wrap; the quadrant does not
/// decide engagement). The path lies in the plane through P, S and a surface point c1 chosen by
/// `method` (midpoint, axial, or hybrid: a blend of the axial point and an average of nearest
/// surface directions along the chord), c1 being mirrored to the active side under a quadrant.
/// The tangent points are found in that plane by OpenSim's damped Gauss-Newton iteration, and
/// the arc is OpenSim's polyline of 1 mm chords (at most 499) along the plane's section. Not the
/// shortest path over the ellipsoid in general; a sphere's great circle when the radii are
/// equal.
class WrapEllipsoid final : public WrapSurface {
 public:
  /// `radii` > 0 (m); throws sinew::Error otherwise.
  WrapEllipsoid(const Vec3& radii, WrapQuadrant quadrant);

  WrapResult Wrap(const Vec3& p_WP, const Vec3& p_WS, const WrapOptions& options) const override;

  const Vec3& radii() const { return radii_; }

 private:
  Vec3 radii_;
  WrapQuadrant quadrant_;
};

}  // namespace sinew::paths

// OpenSim's WrapSphere: a sphere of `radius` centred at the origin of its frame W.
#pragma once

#include <sinew/paths/wrap_quadrant.h>
#include <sinew/paths/wrap_surface.h>

namespace sinew::paths {

/// Wraps a segment over a sphere along a great circle: the arc lies in the plane through P, S
/// and the centre, so P-T1-arc-T2-S is the shortest path over the sphere (docs/wrapping.md).
/// The sphere engages only when the segment P-S passes through it, as in OpenSim; a quadrant
/// then picks the side (possibly the long way round).
class WrapSphere final : public WrapSurface {
 public:
  /// `radius` > 0 (m); throws sinew::Error otherwise.
  WrapSphere(double radius, WrapQuadrant quadrant);

  WrapResult Wrap(const Vec3& p_WP, const Vec3& p_WS, const WrapOptions& options) const override;

  double radius() const { return radius_; }

 private:
  double radius_;
  WrapQuadrant quadrant_;
};

}  // namespace sinew::paths

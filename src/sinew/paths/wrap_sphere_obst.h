// OpenSim's WrapSphereObst: an obstacle-set sphere centred at the origin of its frame W.
#pragma once

#include <sinew/paths/wrap_surface.h>

namespace sinew::paths {

/// Wraps a segment round a sphere as OpenSim's WrapSphereObst does (docs/wrapping.md): in the
/// plane through P, S and the centre, the tangent points of the circle of 0.8 times `radius`
/// turning from P toward S, and the great-circle arc between them; no wrap when the turn is not
/// within 0 to 180 degrees (the segment misses that sphere), P or S is inside it, or P and S
/// are in line with the centre (|P x S| <= 1e-7 m^2, OpenSim's test, reported as a point
/// inside). Its length and quadrant play no part, as in OpenSim.
class WrapSphereObst final : public WrapSurface {
 public:
  /// `radius` > 0 (m), finite; throws sinew::Error otherwise.
  explicit WrapSphereObst(double radius);

  WrapResult Wrap(const Vec3& p_WP, const Vec3& p_WS, const WrapOptions& options) const override;

  double radius() const { return radius_; }

 private:
  double radius_;
};

}  // namespace sinew::paths

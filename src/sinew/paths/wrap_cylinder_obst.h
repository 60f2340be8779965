// OpenSim's WrapCylinderObst: an obstacle-set cylinder about the z axis of its frame W, centred
// at W's origin, that the path always passes round one way (`wrapDirection`).
#pragma once

#include <sinew/paths/wrap_surface.h>

namespace sinew::paths {

/// Wraps a segment round a cylinder as OpenSim's WrapCylinderObst does (docs/wrapping.md): in
/// the cross-section, the tangent points Q (from P) and T (from S) of the circle of 0.8 times
/// `radius` that turn counter-clockwise about z ("righthand") or clockwise ("lefthand"); no wrap
/// when that turn is not within 0 to 180 degrees, or P or S is within the circle. Q's and T's
/// heights divide P's to S's in proportion to the cross-section's path lengths (P-Q, the arc,
/// T-S), and the arc's length is that of the circle's arc (the rise from Q to T left out, as
/// OpenSim does). The cylinder's length and quadrant play no part, as in OpenSim.
class WrapCylinderObst final : public WrapSurface {
 public:
  enum class Direction { kRightHand, kLeftHand };

  /// `radius` > 0 (m), finite; throws sinew::Error otherwise.
  WrapCylinderObst(double radius, Direction direction);

  WrapResult Wrap(const Vec3& p_WP, const Vec3& p_WS, const WrapOptions& options) const override;

  double radius() const { return radius_; }
  Direction direction() const { return direction_; }

 private:
  double radius_;
  Direction direction_;
};

}  // namespace sinew::paths

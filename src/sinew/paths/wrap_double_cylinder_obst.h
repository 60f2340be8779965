// OpenSim's WrapDoubleCylinderObst (Garner and Pandy's obstacle set): two cylinder obstacles,
// U about the z axis of the object's frame W and V about the z axis of a frame V that may be
// fixed to another body, that a path passes round in a given direction each.
#pragma once

#include <sinew/paths/wrap_surface.h>

namespace sinew::paths {

/// Wraps a segment round two cylinders as OpenSim's WrapDoubleCylinderObst does
/// (docs/wrapping.md): P is taken round U first and V second. U engages when the line through
/// P and S (in U's cross-section) passes within U's radius, V when the line from where the path
/// leaves U (or from P) to S passes within V's radius (in V's cross-section); each is then
/// wrapped with the obstacle-set rule (tangent points turning the given way, no wrap past a
/// half turn) and, when both engage, the crossing line from U to V is found by Newton's method
/// so that it is tangent to both. Over each cylinder the path is the helix of the unrolled
/// straight line (its rise included, unlike WrapCylinderObst). The radii are used as given (not
/// 0.8 of them); a point within a radius plus 0.1 mm shrinks that cylinder to pass 0.1 mm inside
/// it. The cylinders' length plays no part. WrapOptions::X_WV must give V's pose in W.
class WrapDoubleCylinderObst final : public WrapSurface {
 public:
  enum class Direction { kRightHand, kLeftHand };
  /// Radii > 0 (m), finite; throws sinew::Error otherwise.
  WrapDoubleCylinderObst(double radius_u, Direction direction_u, double radius_v,
                         Direction direction_v);

  /// P and S in W. The result's T1, T2 (when on_first) lie on U, its T3, T4 (when on_second)
  /// on V, all given in W. `wrapped` is always true, as in OpenSim (on neither cylinder: the
  /// segment stays straight).
  WrapResult Wrap(const Vec3& p_WP, const Vec3& p_WS, const WrapOptions& options) const override;

  double radius_u() const { return radius_u_; }
  double radius_v() const { return radius_v_; }
  Direction direction_u() const { return direction_u_; }
  Direction direction_v() const { return direction_v_; }

 private:
  double radius_u_, radius_v_;
  Direction direction_u_, direction_v_;
};

}  // namespace sinew::paths

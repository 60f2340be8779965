// OpenSim's `quadrant` of a wrap object: the half-space of the wrap frame W (x >= 0, y < 0, ...)
// on which the path may wrap, and OpenSim's rule for whether a constrained surface engages.
#pragma once

#include <sinew/math/types.h>

#include <string>

namespace sinew::paths {

/// The active side of a wrap object: `sign` (+1 or -1) of W's `axis` (0 x, 1 y, 2 z), or
/// sign 0 for "all" (unconstrained). A point is on the positive side when its coordinate is
/// >= 0, as in OpenSim (a point exactly on the plane counts as positive).
struct WrapQuadrant {
  int axis = 0;
  int sign = 0;

  bool constrained() const { return sign != 0; }
  /// +1 or -1: the side of the plane `axis = 0` the point p_W is on.
  int SideOf(const Vec3& p_W) const { return p_W[axis] >= 0.0 ? 1 : -1; }
  bool OnActiveSide(const Vec3& p_W) const { return SideOf(p_W) == sign; }
  /// The unit vector along the active side's axis (+-x, +-y, +-z).
  Vec3 ActiveDirection() const { return static_cast<double>(sign) * Vec3::Unit(axis); }
};

/// Reads OpenSim's quadrant text: "all" (also "All", "ALL", "Unassigned" or empty: the default),
/// "x", "+x", "-x" and the same for y and z, in either case. Anything else throws sinew::Error
/// naming `wrap_name`.
WrapQuadrant ParseWrapQuadrant(const std::string& text, const std::string& wrap_name);

/// OpenSim's decision for a constrained surface when P or S is on the active side.
enum class QuadrantEngagement { kNoWrap, kWrapped, kMandatory };

/// OpenSim's rule when P or S lies on the active side of a constrained surface: the wrap is
/// mandatory when the segment crosses the surface; otherwise, when P and S are on opposite sides
/// and the line's closest point to the surface's centre or axis (p_WM) is not on the active side,
/// the path is pulled around the active side (a plain wrap); else there is no wrap.
QuadrantEngagement EngageOnActiveSide(const WrapQuadrant& quadrant, const Vec3& p_WP,
                                      const Vec3& p_WS, const Vec3& p_WM, bool segment_crosses);

}  // namespace sinew::paths

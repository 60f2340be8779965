// The contract between a muscle path and a wrapping surface (WrapSphere, WrapCylinder,
// WrapEllipsoid, WrapTorus, ...): given the two path points on either side of the surface,
// expressed in the surface's own frame W, a surface says whether the straight segment between
// them is wrapped and, if so, where the path leaves the straight line (the two tangent points)
// and how long the path is on the surface between them.
//
// Why tangent points suffice for moment arms and speeds: a wrapped path that is locally the
// shortest path over the surface does not change length to first order when a tangent point
// moves along the surface. The path's length derivative is then the sum, over its straight
// segments, of the unit direction of each segment dotted with the relative velocity of its
// ends, with the tangent points moving rigidly with the surface's body. OpenSim's moment arms
// and lengthening speeds use this rule (forces along the straight segments) even where its
// path is not exactly the shortest: its WrapCylinder's tangent points leave a kink when P and S
// are at different heights, so there this rule, which matches OpenSim's moment arms, differs
// from -dL/dq of the length (docs/wrapping.md: 1.5e-4 m on arm26's brachialis).
#pragma once

#include <sinew/math/transform.h>
#include <sinew/math/types.h>

#include <vector>

namespace sinew::paths {

/// How a path uses one wrap object (OpenSim's PathWrap).
struct WrapOptions {
  /// OpenSim's `method` for WrapEllipsoid: hybrid, midpoint or axial (ignored by other shapes).
  enum class Method { kHybrid, kMidpoint, kAxial } method = Method::kHybrid;
  /// Whether this is the path's only wrap object. OpenSim's WrapCylinder refines its tangent
  /// points iteratively (to 0.1 degree of tangency) only when a path has two or more wrap
  /// objects, so the same segment gives slightly different lengths in the two cases; the path
  /// must say which applies to reproduce OpenSim's lengths. (OpenSim before 4.4 refined in
  /// both cases: a path following it passes false, see paths::CylinderRefinement.)
  bool single_wrap = true;
  /// Whether to fill WrapResult::arc_points (for drawing). Off by default: sampling the arc
  /// costs more than the wrap itself, and lengths and derivatives do not need it.
  bool with_arc_points = false;
  /// Surfaces on two frames only (WrapDoubleCylinderObst): the pose of the second frame V (the
  /// V cylinder's, fixed to another body) in W at this pose. The path sets it; others ignore it.
  Transform X_WV;
  /// How a refining WrapCylinder checks its second tangent point T2 in each refinement step:
  /// against the helix sample next to T2 placed after T1 moved in that step (OpenSim 4.4.1 and
  /// later; true), or against the sample of the helix the step started with (OpenSim up to
  /// 4.4.0, which sampled the helix from T1's axis point taken before the step; false). The two
  /// refine to tangent points a few 1e-5 m apart along the cylinder (docs/wrapping.md).
  bool t2_checked_after_t1_moves = true;
};

/// What wrapping the segment from P to S over a surface gives, all in the surface frame W.
struct WrapResult {
  /// False when the straight segment P-S does not touch the surface, or the wrap is excluded
  /// by its quadrant: the path then stays straight between P and S.
  bool wrapped = false;
  /// OpenSim's "mandatory" wrap: the segment crosses the surface (on its active side), so a path
  /// with several segments in the wrap's range must wrap this one (the first such segment).
  /// A wrap that is not mandatory (OpenSim's plain "wrapped": an unconstrained WrapSphere, or a
  /// quadrant that pulls the path around) competes with the range's other wrapped segments, and
  /// the path keeps the one that lengthens the path least. Needed only to choose the segment.
  bool mandatory = false;
  /// P or S lies inside the surface (OpenSim's "insideRadius"): no wrap. The path code needs it
  /// for OpenSim's one reordering rule (a path with several wrap objects tries the second one
  /// first when the first does not wrap and the second has a point inside it).
  bool point_inside = false;
  Vec3 p_WT1 = Vec3::Zero();  ///< first tangent point (where the path leaves the line from P)
  Vec3 p_WT2 = Vec3::Zero();  ///< second tangent point (where it leaves the surface toward S)
  double arc_length = 0.0;    ///< length of the path on the surface, from T1 to T2 (m)
  /// Whether a wrapped path goes over the surface from T1 to T2: always, except for a surface
  /// on two frames (WrapDoubleCylinderObst), whose path may pass over its second cylinder only,
  /// or over neither (then `wrapped` with neither means OpenSim's wrap that leaves the segment
  /// straight: it still takes part, with no change of length, in the choice of segment).
  bool on_first = true;
  /// Surfaces on two frames only: the path also (or only) goes over the second cylinder, from
  /// T3 to T4 (in W, but fixed to the second frame V), after a straight piece from T2 (when
  /// on_first) or from P; the path is then P, [T1, arc, T2,] T3, second arc, T4, S.
  bool on_second = false;
  Vec3 p_WT3 = Vec3::Zero();
  Vec3 p_WT4 = Vec3::Zero();
  double second_arc_length = 0.0;  ///< the path's length over the second cylinder (m)
  /// Points along the path on the surface, from T1 to T2 inclusive, for drawing; filled only
  /// when WrapOptions::with_arc_points is set.
  std::vector<Vec3> arc_points;
  /// The same over the second cylinder (on_second), from T3 to T4 inclusive.
  std::vector<Vec3> second_arc_points;
};

/// A wrapping surface fixed in its frame W. Stateless and thread-safe: Wrap is const.
class WrapSurface {
 public:
  virtual ~WrapSurface() = default;
  /// Wraps the segment from p_WP to p_WS (the path points before and after the surface).
  virtual WrapResult Wrap(const Vec3& p_WP, const Vec3& p_WS, const WrapOptions& options) const = 0;
};

}  // namespace sinew::paths

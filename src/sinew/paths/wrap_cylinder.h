// OpenSim's WrapCylinder: a cylinder of `radius` about the z axis of its frame W, centred at
// W's origin, `length` long (the length only decides whether a wrap counts, see below).
#pragma once

#include <sinew/paths/wrap_quadrant.h>
#include <sinew/paths/wrap_surface.h>

namespace sinew::paths {

/// Wraps a segment over a cylinder as OpenSim does (docs/wrapping.md): the tangent points are
/// found on the infinite cylinder by OpenSim's construction (the tangent lines of the cross
/// sections through P and S, slid along the cylinder to a plane through P, S and an apex point),
/// the path between them is a helix, and the wrap is dropped when both tangent points lie beyond
/// the ends (|z| > length / 2). The construction is exact when P and S are at the same height
/// and close to the shortest path otherwise; with two or more wrap objects on a path
/// (options.single_wrap false) OpenSim refines the tangent points to 0.1 degree of tangency.
class WrapCylinder final : public WrapSurface {
 public:
  /// `radius` > 0 and `length` > 0 (m); throws sinew::Error otherwise.
  WrapCylinder(double radius, double length, WrapQuadrant quadrant);

  WrapResult Wrap(const Vec3& p_WP, const Vec3& p_WS, const WrapOptions& options) const override;

  double radius() const { return radius_; }
  double length() const { return length_; }

 private:
  double radius_;
  double length_;
  WrapQuadrant quadrant_;
};

}  // namespace sinew::paths

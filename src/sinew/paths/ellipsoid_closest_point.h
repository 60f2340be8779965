// The point of an ellipsoid (or of an ellipse) closest to a given point, by the Newton iteration
// on the Lagrange-multiplier equation of Eberly (Graphics Gems IV) that OpenSim's WrapEllipsoid
// uses, with OpenSim's special cases near the principal planes, so that wrapping over an
// ellipsoid picks the same plane OpenSim picks.
#pragma once

#include <sinew/math/types.h>

namespace sinew::paths {

/// The point of the ellipsoid sum (x_i / radii_i)^2 = 1 (centred at the origin, axes along the
/// frame's) closest to `p`. When `plane_axis` is 0, 1 or 2 the problem is solved in the
/// ellipse where that coordinate is p's own (OpenSim's reduction for points on a principal
/// plane); with -1, that reduction is chosen as OpenSim does (a coordinate within 2e-13 of 0,
/// the narrowest such cross-section), else the full 3-d iteration runs. When the 3-d iteration
/// does not converge in 64 steps, `fallback` is returned (OpenSim leaves its output unchanged).
Vec3 CalcClosestPointOnEllipsoid(const Vec3& radii, const Vec3& p, int plane_axis,
                                 const Vec3& fallback);

/// The point of the ellipse (x / a)^2 + (y / b)^2 = 1 closest to (u, v), as {x, y}; exact
/// special cases on the axes (within 2e-13), else at most 64 Newton steps.
Eigen::Vector2d CalcClosestPointOnEllipse(double a, double b, double u, double v);

}  // namespace sinew::paths

// OpenSim's solver for a wrap's tangent point on an ellipsoid: the point T of the ellipsoid, in
// a given plane, whose tangent plane holds the path point P outside it.
#pragma once

#include <sinew/math/types.h>

namespace sinew::paths {

/// Moves `r` (the start, on or near the ellipsoid sum (x_i / radii_i)^2 = 1) to a point of the
/// ellipsoid in the plane n . x + d = 0 whose tangent plane holds `p`, by OpenSim's damped
/// Gauss-Newton iteration (WrapEllipsoid::calcTangentPoint): four residuals (in the plane, on
/// the ellipsoid, and the tangent plane through r with offset d1 holding r and p), a
/// Levenberg-Marquardt step damped near P's radial direction and divided by 16, then extended
/// by doubling while it helps; it stops when the squared residuals sum below 1e-8, or after 50
/// steps. OpenSim calls it in coordinates scaled so the semi-axes average 1, and so must the
/// caller, for the same stopping rule. `p_level` is sum (p_i / radii_i)^2 - 1: when it is
/// within 1e-4 of 0, p is on the surface and is the tangent point.
void SolveEllipsoidTangentPoint(const Vec3& radii, const Vec3& p, double p_level, const Vec3& n,
                                double d, Vec3& r);

}  // namespace sinew::paths

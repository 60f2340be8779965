// Point contact between two shapes (half-space/sphere, sphere/sphere), with Simbody's
// conventions: where the shapes overlap, how deep, the normal, the effective radius.
#pragma once

#include <sinew/contact/contact_shape.h>
#include <sinew/math/transform.h>

#include <optional>

namespace sinew::contact {

/// The overlap of shape 1 and shape 2: `depth` (m, > 0) along `n_G` (unit, from shape 1
/// towards shape 2, in G), centred at `p_G` (midway through the overlap), and the effective
/// radius of curvature R = r1 r2 / (r1 + r2) (a half-space's is infinite: R = r of the sphere).
struct PointContact {
  Vec3 p_G = Vec3::Zero();
  Vec3 n_G = Vec3::UnitY();
  double depth = 0.0;
  double radius = 0.0;
};

/// True when two shapes of these kinds can make a point contact (a sphere with a half-space or
/// a sphere); shape 1 must then be the half-space when there is one.
bool IsPointContactPair(ShapeKind kind1, ShapeKind kind2);

/// The contact of shape 1 posed at X_G1 (its frame C in ground) with shape 2 at X_G2, or
/// nullopt when they do not overlap (or concentric spheres: no normal).
std::optional<PointContact> FindPointContact(const ContactShape& shape1, const Transform& X_G1,
                                             const ContactShape& shape2, const Transform& X_G2);

}  // namespace sinew::contact

// An ellipsoid as a Bullet convex shape, so that Bullet's GJK and EPA collide it with any other
// convex shape. Bullet has no ellipsoid: a btMultiSphereShape with one sphere and non-uniform
// local scaling moves the sphere's support point by the scaling, which is not the ellipsoid's
// support point (for semi-axes A = diag(a, b, c) that is A^2 d / |A d|, not A d / |d|), so
// depths would be wrong by up to (max - min) semi-axis; a convex hull of sampled points is
// exact only at its samples. This shape gives GJK the exact support point. Private to the
// contact layer (it includes Bullet).
#pragma once

#include <BulletCollision/CollisionShapes/btConvexInternalShape.h>

namespace sinew::contact {

/// Semi-axes along the shape's x, y, z; Bullet's margin (default 0) grows it all round.
class BulletEllipsoid final : public btConvexInternalShape {
 public:
  explicit BulletEllipsoid(const btVector3& radii);

  btVector3 localGetSupportingVertexWithoutMargin(const btVector3& d) const override;
  void batchedUnitVectorGetSupportingVertexWithoutMargin(const btVector3* d, btVector3* out,
                                                         int n) const override;
  /// The exact box of the ellipsoid grown by the margin: half-width sqrt(sum_j (R_ij r_j)^2).
  void getAabb(const btTransform& t, btVector3& aabb_min, btVector3& aabb_max) const override;
  /// A solid ellipsoid's: m / 5 (b^2 + c^2, a^2 + c^2, a^2 + b^2).
  void calculateLocalInertia(btScalar mass, btVector3& inertia) const override;
  const char* getName() const override { return "SinewEllipsoid"; }

 private:
  btVector3 radii_;
};

}  // namespace sinew::contact

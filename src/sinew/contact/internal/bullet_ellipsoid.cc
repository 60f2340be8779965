#include <sinew/contact/internal/bullet_ellipsoid.h>

#include <cmath>

namespace sinew::contact {

BulletEllipsoid::BulletEllipsoid(const btVector3& radii) : radii_(radii) {
  m_shapeType = CUSTOM_CONVEX_SHAPE_TYPE;
  setMargin(0.0);
}

btVector3 BulletEllipsoid::localGetSupportingVertexWithoutMargin(const btVector3& d) const {
  // The point maximizing d . p on p = A u, |u| = 1: u = A d / |A d|, so p = A^2 d / |A d|.
  const btVector3 Ad = radii_ * d;
  const btScalar length = Ad.length();
  if (!(length > 0.0)) return btVector3(radii_.x(), 0.0, 0.0);
  return radii_ * Ad / length;
}

void BulletEllipsoid::batchedUnitVectorGetSupportingVertexWithoutMargin(const btVector3* d,
                                                                        btVector3* out,
                                                                        int n) const {
  for (int i = 0; i < n; ++i) out[i] = localGetSupportingVertexWithoutMargin(d[i]);
}

void BulletEllipsoid::getAabb(const btTransform& t, btVector3& aabb_min,
                              btVector3& aabb_max) const {
  const btMatrix3x3& R = t.getBasis();
  btVector3 half;
  for (int i = 0; i < 3; ++i) {
    const btVector3 row = R.getRow(i) * radii_;
    half[i] = row.length() + getMargin();
  }
  aabb_min = t.getOrigin() - half;
  aabb_max = t.getOrigin() + half;
}

void BulletEllipsoid::calculateLocalInertia(btScalar mass, btVector3& inertia) const {
  const btVector3 r2 = radii_ * radii_;
  inertia = btVector3(r2.y() + r2.z(), r2.x() + r2.z(), r2.x() + r2.y()) * (mass / 5.0);
}

}  // namespace sinew::contact

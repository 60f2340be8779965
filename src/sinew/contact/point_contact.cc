#include <sinew/contact/point_contact.h>

namespace sinew::contact {

bool IsPointContactPair(ShapeKind kind1, ShapeKind kind2) {
  return kind2 == ShapeKind::kSphere &&
         (kind1 == ShapeKind::kHalfSpace || kind1 == ShapeKind::kSphere);
}

std::optional<PointContact> FindPointContact(const ContactShape& shape1, const Transform& X_G1,
                                             const ContactShape& shape2, const Transform& X_G2) {
  PointContact c;
  if (shape1.kind == ShapeKind::kHalfSpace && shape2.kind == ShapeKind::kSphere) {
    // The sphere's centre in the half-space's frame H: the solid is x > 0.
    const Vec3 p_HS = X_G1.Inverse() * X_G2.p;
    c.depth = shape2.radius + p_HS.x();
    if (!(c.depth > 0.0)) return std::nullopt;
    c.n_G = X_G1.R * Vec3(-1.0, 0.0, 0.0);
    c.p_G = X_G1 * Vec3(c.depth / 2.0, p_HS.y(), p_HS.z());
    c.radius = shape2.radius;
    return c;
  }
  if (shape1.kind == ShapeKind::kSphere && shape2.kind == ShapeKind::kSphere) {
    const Vec3 delta = X_G2.p - X_G1.p;
    const double distance = delta.norm();
    if (distance == 0.0) return std::nullopt;
    c.depth = shape1.radius + shape2.radius - distance;
    if (!(c.depth > 0.0)) return std::nullopt;
    c.n_G = delta / distance;
    c.p_G = X_G1.p + (shape1.radius - c.depth / 2.0) * c.n_G;
    c.radius = shape1.radius * shape2.radius / (shape1.radius + shape2.radius);
    return c;
  }
  return std::nullopt;
}

}  // namespace sinew::contact

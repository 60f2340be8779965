#include <sinew/opensim/collision_parts.h>

namespace sinew::opensim {

std::vector<viz::CollisionPart> CollisionPartsOf(const contact::CollisionModel& model) {
  using Shape = viz::CollisionPart::Shape;
  std::vector<viz::CollisionPart> parts;
  for (const contact::CollisionCylinder& c : model.shapes) {
    const Vec3 axis = c.p_B_end - c.p_B_start;
    const double length = axis.norm();
    if (!(length > 0.0)) continue;
    const Mat3 R =
        Eigen::Quaterniond::FromTwoVectors(Vec3::UnitY(), axis / length).toRotationMatrix();
    parts.push_back({"collision_cylinder", c.body, Shape::kCylinder,
                     Transform(R, 0.5 * (c.p_B_start + c.p_B_end)),
                     Vec3(c.radius, 0.5 * length, c.radius)});
  }
  for (const contact::CollisionGeometry& g : model.geometry) {
    viz::CollisionPart part{g.name, g.body, Shape::kSphere, g.X_BS, Vec3::Constant(g.radius)};
    switch (g.kind) {
      case contact::CollisionShapeKind::kSphere:
        break;
      case contact::CollisionShapeKind::kBox:
        part.shape = Shape::kBox;
        part.half_size = g.half_extents;
        break;
      case contact::CollisionShapeKind::kHalfSpace:
        part.shape = Shape::kHalfSpace;
        break;
      case contact::CollisionShapeKind::kCylinder:  // the drawn cylinder's axis is y, OpenSim's z
        part.shape = Shape::kCylinder;
        part.X_BS =
            g.X_BS *
            Transform(
                Eigen::Quaterniond::FromTwoVectors(Vec3::UnitY(), Vec3::UnitZ()).toRotationMatrix(),
                Vec3::Zero());
        part.half_size = Vec3(g.radius, g.half_length, g.radius);
        break;
      case contact::CollisionShapeKind::kEllipsoid:
        part.shape = Shape::kEllipsoid;
        part.half_size = g.radii;
        break;
      case contact::CollisionShapeKind::kConvexMesh:
      case contact::CollisionShapeKind::kTriangleMesh:
        continue;  // the scene draws the ContactMesh itself (its triangles, not its hull)
    }
    parts.push_back(part);
  }
  return parts;
}

}  // namespace sinew::opensim

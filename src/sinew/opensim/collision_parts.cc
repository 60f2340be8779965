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
    if (g.kind == contact::CollisionShapeKind::kBox) {
      part.shape = Shape::kBox;
      part.half_size = g.half_extents;
    } else if (g.kind == contact::CollisionShapeKind::kHalfSpace) {
      part.shape = Shape::kHalfSpace;
    }
    parts.push_back(part);
  }
  return parts;
}

}  // namespace sinew::opensim

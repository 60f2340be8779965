#include <sinew/viz/collision_parts.h>
#include <sinew/viz/primitive_shapes.h>

namespace sinew::viz {
namespace {

constexpr double kSlabHalfWidth = 2.0;       // m
constexpr double kSlabHalfThickness = 0.01;  // m

}  // namespace

void AddCollisionParts(const std::vector<CollisionPart>& parts, VisualScene& scene) {
  for (const CollisionPart& c : parts) {
    if (c.body < 0 || c.body >= static_cast<int>(scene.bodies.size())) continue;
    VisualPart part;
    part.name = c.name;
    part.X_BG = c.X_BS;
    part.color = kContactColor;
    part.source = "collision";
    switch (c.shape) {
      case CollisionPart::Shape::kCylinder:
        part.mesh = UnitCylinder();
        part.scale = c.half_size;
        break;
      case CollisionPart::Shape::kSphere:
        part.mesh = UnitSphere();
        part.scale = Vec3::Constant(c.half_size.x());
        break;
      case CollisionPart::Shape::kEllipsoid:
        part.mesh = UnitSphere();
        part.scale = c.half_size;
        break;
      case CollisionPart::Shape::kBox:
        part.mesh = UnitBox();
        part.scale = c.half_size;
        break;
      case CollisionPart::Shape::kHalfSpace:
        part.mesh = UnitBox();
        part.X_BG = c.X_BS * Transform::Translation(Vec3(kSlabHalfThickness, 0, 0));
        part.scale = Vec3(kSlabHalfThickness, kSlabHalfWidth, kSlabHalfWidth);
        part.unbounded = true;
        break;
    }
    scene.bodies[c.body].parts.push_back(std::move(part));
  }
}

}  // namespace sinew::viz

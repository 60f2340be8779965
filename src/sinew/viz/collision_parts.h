// Collision shapes drawn beside a model's visual geometry (the seed's collision cylinders and
// environment shapes when collision is enabled), in the contact colour.
#pragma once

#include <sinew/math/transform.h>
#include <sinew/viz/visual_scene.h>

#include <string>
#include <vector>

namespace sinew::viz {

/// One collision shape to draw, fixed to body `body` (spec index, 0 = ground) with its frame
/// S at X_BS: a cylinder along S's y (`half_size` = radius, half length, radius), a sphere
/// (`half_size.x()` its radius), a box (`half_size` its half extents), or a half-space (the
/// solid x > 0 of S, drawn as a 4 m square slab just inside it).
struct CollisionPart {
  enum class Shape { kCylinder, kSphere, kBox, kHalfSpace, kEllipsoid };
  std::string name;
  int body = 0;
  Shape shape = Shape::kSphere;
  Transform X_BS;
  Vec3 half_size = Vec3::Zero();
};

/// Appends `parts` to the bodies of `scene` (one VisualBody per spec body) in kContactColor.
void AddCollisionParts(const std::vector<CollisionPart>& parts, VisualScene& scene);

}  // namespace sinew::viz

// The parser's collision options (OpenSimParser::EnableCollision, SetGroundPlane,
// AddEnvironmentBox, SetContactMaterial, SetFrictionSlipSpeed), as one value.
#pragma once

#include <sinew/contact/collision_model.h>

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace sinew::opensim {

/// What the parser's collision options say.
struct CollisionSettings {
  int family_1 = 1;
  int family_2 = 2;
  std::optional<double> ground_plane;                   ///< height of the plane y = H
  std::vector<contact::CollisionGeometry> environment;  ///< shapes fixed to ground
  contact::CollisionMaterial material;                  ///< the default material
  /// Per-shape materials: a body name (its cylinders and contact geometry), a contact
  /// geometry's name or an environment shape's name.
  std::vector<std::pair<std::string, contact::CollisionMaterial>> overrides;
  double slip_speed = 1e-3;  ///< SMC friction regularization (m/s)
};

/// True for the OpenSim contact geometry classes that collide when collision is enabled
/// (ContactHalfSpace, ContactSphere, ContactCylinder, ContactEllipsoid, ContactMesh); the
/// parser warns about any other class and leaves it out.
bool IsCollisionShapeClass(std::string_view opensim_class);

}  // namespace sinew::opensim

// Contact shapes fixed to bodies, as OpenSim's ContactGeometry describes them (Simbody's
// ContactGeometry conventions): a half-space, a sphere or a triangle mesh, posed in its body.
#pragma once

#include <sinew/math/transform.h>
#include <sinew/math/types.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace sinew::contact {

/// The kinds of contact geometry the contact forces handle.
enum class ShapeKind {
  kHalfSpace,  ///< OpenSim's ContactHalfSpace: the points with x > 0 in its frame C; its
               ///< outward normal is -x_C.
  kSphere,     ///< ContactSphere: centred at C's origin.
  kMesh,       ///< ContactMesh: triangles given in C.
};

/// A triangle mesh in the frame of its shape (m), triangles counter-clockwise from outside.
struct ShapeMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;
};

/// One contact shape: its body (engine index, 0 = ground) and pose X_BC in that body.
struct ContactShape {
  std::string name;  ///< The geometry's name in the model.
  ShapeKind kind = ShapeKind::kSphere;
  int body = 0;
  Transform X_BC;
  double radius = 0.0;                      ///< kSphere: m
  std::shared_ptr<const ShapeMesh> mesh;    ///< kMesh
};

/// Material parameters of one shape, in OpenSim's units: stiffness (Hunt-Crossley: Pa, a
/// Young's-modulus-like k with F = 4/3 k sqrt(R) d^(3/2) for two equal materials halved;
/// elastic foundation: N/m^3, pressure per metre of depth), dissipation (s/m), friction
/// coefficients (static, dynamic: none; viscous: s/m).
struct ContactMaterial {
  double stiffness = 0.0;
  double dissipation = 0.0;
  double static_friction = 0.0;
  double dynamic_friction = 0.0;
  double viscous_friction = 0.0;
};

/// The friction force magnitude of OpenSim's (Simbody's) contact models for a normal force
/// `f_normal` (N) and a slip speed `v_slip` (m/s): f_normal (min(v_r, 1) (u_d + 2 (u_s - u_d) /
/// (1 + v_r^2)) + u_v v_slip), v_r = v_slip / `transition_velocity`. It rises linearly to
/// u_s f_normal at the transition velocity, then falls towards u_d f_normal.
double FrictionForce(double f_normal, double v_slip, double static_friction,
                     double dynamic_friction, double viscous_friction, double transition_velocity);

}  // namespace sinew::contact

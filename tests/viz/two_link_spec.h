// Test helper: a small hand-made model (ground, a pendulum link, a tip welded below it) with
// a mesh, an analytic sphere and a missing mesh, and a motion that swings it.
#pragma once

#include <sinew/math/rotation.h>
#include <sinew/model/model_spec.h>
#include <sinew/viz/body_motion.h>

#include <string>

namespace sinew::viz::testing {

inline const std::string kDataDir = SINEW_TEST_DATA_DIR;

// Ground, a "link" body hanging from a pin at the origin, and a "tip" body below it.
inline model::ModelSpec TwoLinkSpec() {
  model::ModelSpec spec;
  spec.name = "two_link";
  spec.file = kDataDir + "/two_link.osim";  // need not exist: only its folder is searched
  spec.bodies.resize(3);
  spec.bodies[0].name = "ground";
  spec.bodies[1].name = "link";
  spec.bodies[1].path = "/bodyset/link";
  spec.bodies[2].name = "tip";
  spec.bodies[2].path = "/bodyset/tip";
  model::JointSpec pin;
  pin.name = "pin";
  pin.parent_body = 0;
  pin.child_body = 1;
  pin.X_BM = Transform::Translation(Vec3(0, 0.5, 0));
  model::JointSpec weld;
  weld.name = "weld";
  weld.parent_body = 1;
  weld.child_body = 2;
  weld.X_PF = Transform::Translation(Vec3(0, -0.5, 0));
  spec.joints = {pin, weld};
  model::GeometrySpec mesh;
  mesh.name = "patella";
  mesh.type = "Mesh";
  mesh.mesh_file = "r_patella.vtp";
  mesh.scale_factors = Vec3(2, 2, 2);
  mesh.color = Vec3(1, 0, 0);
  model::GeometrySpec sphere;
  sphere.name = "ball";
  sphere.type = "Sphere";
  sphere.dimensions["radius"] = {0.1};
  sphere.X_BG = Transform::Translation(Vec3(0, 0.2, 0));
  spec.bodies[1].geometry = {mesh, sphere};
  model::GeometrySpec missing = mesh;
  missing.name = "lost";
  missing.mesh_file = "not_there.vtp";
  spec.bodies[2].geometry = {missing};
  return spec;
}

// Frames at times t0 + dt*k, k = 0..n-1: the link turned about z by `rate`*k rad.
inline BodyMotion SwingMotion(int n, double t0, double dt, double rate) {
  BodyMotion motion;
  for (int k = 0; k < n; ++k) {
    const Transform X_GL(RotationAboutAxis(Vec3::UnitZ(), rate * k), Vec3::Zero());
    const Transform X_GB1 = X_GL * Transform::Translation(Vec3(0, -0.5, 0));
    motion.times.push_back(t0 + dt * k);
    motion.X_GB.push_back({Transform(), X_GB1, X_GB1 * Transform::Translation(Vec3(0, -0.5, 0))});
  }
  return motion;
}

}  // namespace sinew::viz::testing

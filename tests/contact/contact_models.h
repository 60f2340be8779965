// Small OpenSim 4 models written as text for the contact tests: one free body with contact
// spheres above a ground half-space, parsing them into a System, and running collision under NSC.
#pragma once

#include <sinew/contact/collision_contact_provider.h>
#include <sinew/contact/contact_force.h>
#include <sinew/engine/nsc_integrator.h>
#include <sinew/engine/system.h>
#include <sinew/io/osim_reader.h>
#include <sinew/opensim/parser.h>

#include <array>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace sinew::testing {

/// A free body "body" (mass `mass`, central inertia diag(`inertia`)) under `gravity`, with a
/// ground ContactHalfSpace "floor" whose solid is y < 0, then the contact geometry `geometry`
/// (XML) in the ContactGeometrySet, and `forces` in the ForceSet.
inline std::string FreeBodyModel(double mass, const Vec3& inertia, const Vec3& gravity,
                                 const std::string& geometry, const std::string& forces) {
  std::ostringstream m;
  m.precision(17);
  m << R"(<OpenSimDocument Version="40000"><Model name="contact">
<gravity>)"
    << gravity.transpose() << R"(</gravity><Ground name="ground"/>
<BodySet><objects><Body name="body"><mass>)"
    << mass << "</mass><inertia>" << inertia.transpose()
    << R"( 0 0 0</inertia></Body></objects></BodySet>
<JointSet><objects><FreeJoint name="free"><socket_parent_frame>/ground</socket_parent_frame>
<socket_child_frame>/bodyset/body</socket_child_frame><coordinates>
<Coordinate name="rx"/><Coordinate name="ry"/><Coordinate name="rz"/>
<Coordinate name="tx"/><Coordinate name="ty"/><Coordinate name="tz"/>
</coordinates></FreeJoint></objects></JointSet>
<ForceSet><objects>)"
    << forces << R"(</objects></ForceSet>
<ContactGeometrySet><objects>
<ContactHalfSpace name="floor"><socket_frame>/ground</socket_frame>
<orientation>0 0 -1.5707963267948966</orientation></ContactHalfSpace>
)" << geometry
    << "</objects></ContactGeometrySet></Model></OpenSimDocument>";
  return m.str();
}

/// FreeBodyModel with ContactSpheres "s0", "s1", ... of radius `radius` at `centers` (in the
/// body frame).
inline std::string FreeBodyContactModel(double mass, const Vec3& inertia, const Vec3& gravity,
                                        double radius, const std::vector<Vec3>& centers,
                                        const std::string& forces) {
  std::ostringstream g;
  g.precision(17);
  for (size_t i = 0; i < centers.size(); ++i) {
    g << "<ContactSphere name=\"s" << i << "\"><socket_frame>/bodyset/body</socket_frame>"
      << "<location>" << centers[i].transpose() << "</location><radius>" << radius
      << "</radius></ContactSphere>\n";
  }
  return FreeBodyModel(mass, inertia, gravity, g.str(), forces);
}

/// A HuntCrossleyForce "contact" between the floor and spheres s0 ... s<n-1>, every material
/// with these parameters (us = ud = `friction`, no viscous friction).
inline std::string HuntCrossleyText(int spheres, double stiffness, double dissipation,
                                    double friction, double transition_velocity) {
  std::ostringstream f;
  f.precision(17);
  f << "<HuntCrossleyForce name=\"contact\"><HuntCrossleyForce::ContactParametersSet>"
    << "<objects><HuntCrossleyForce::ContactParameters><geometry>floor";
  for (int i = 0; i < spheres; ++i) f << " s" << i;
  f << "</geometry><stiffness>" << stiffness << "</stiffness><dissipation>" << dissipation
    << "</dissipation><static_friction>" << friction << "</static_friction><dynamic_friction>"
    << friction << "</dynamic_friction><viscous_friction>0</viscous_friction>"
    << "</HuntCrossleyForce::ContactParameters></objects>"
    << "</HuntCrossleyForce::ContactParametersSet><transition_velocity>" << transition_velocity
    << "</transition_velocity></HuntCrossleyForce>";
  return f.str();
}

/// A finalized system parsed from .osim text (`file` names it in errors).
inline std::unique_ptr<engine::System> ParseContactModel(const std::string& text,
                                                         const std::string& file) {
  opensim::OpenSimParser parser;
  const model::ModelSpec spec = io::ReadOsimString(text, file);
  auto system = std::make_unique<engine::System>(spec.gravity);
  parser.ParseSpec(*system, spec);
  system->Finalize();
  return system;
}

/// The system's contact force named `name`.
inline const contact::ContactForce& FindContactForce(const engine::System& system,
                                                     const std::string& name) {
  for (const auto& f : system.force_elements()) {
    const auto* c = dynamic_cast<const contact::ContactForce*>(f.get());
    if (c && c->name() == name) return *c;
  }
  throw Error("no contact force " + name);
}

/// Runs `system` from `state` to `t_end` under NSC with the collision shapes `model` (friction
/// `friction`, no restitution, the pairs overlapping at the start left out), h = 1 ms and a
/// tight solver (1e-12, 1000 iterations); returns the number of contacts of the last step.
inline size_t RunCollisionNsc(const engine::System& system, engine::State& state,
                              const contact::CollisionModel& model, double friction, double t_end) {
  std::vector<Transform> X_GB;
  contact::GatherBodyPoses(state, X_GB);
  auto provider = std::make_shared<contact::CollisionContactProvider>(
      model, std::nullopt, contact::NscMaterial{.friction = friction, .restitution = 0.0}, X_GB);
  engine::IntegratorSettings settings;
  settings.step = 1e-3;
  engine::NscSettings nsc;
  nsc.solver.max_iterations = 1000;
  nsc.solver.tolerance = 1e-12;
  engine::NscIntegrator integrator(system, provider, settings, nsc);
  integrator.StepTo(state, t_end);
  return integrator.last_contacts().size();
}

/// A closed triangle mesh of the box with half extents `h` about its origin (a ContactMesh
/// cube): its 8 corners (index i: x, y, z positive for bits 0, 1, 2), 12 triangles
/// counter-clockwise from outside.
inline std::shared_ptr<contact::ShapeMesh> MakeBoxMesh(const Vec3& h) {
  auto mesh = std::make_shared<contact::ShapeMesh>();
  for (int i = 0; i < 8; ++i)
    mesh->vertices.push_back(
        Vec3(i & 1 ? h.x() : -h.x(), i & 2 ? h.y() : -h.y(), i & 4 ? h.z() : -h.z()));
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      // The face's corners in order round it (the other two bits as a Gray code).
      const int a = 1 << ((axis + 1) % 3), b = 1 << ((axis + 2) % 3), s = side << axis;
      const std::array<int, 4> ring = {s, s | a, s | a | b, s | b};
      const Vec3 out = (side ? 1.0 : -1.0) * Vec3::Unit(axis);
      for (const std::array<int, 3>& t : {std::array<int, 3>{ring[0], ring[1], ring[2]},
                                          std::array<int, 3>{ring[0], ring[2], ring[3]}}) {
        const Vec3& p0 = mesh->vertices[t[0]];
        const Vec3 n = (mesh->vertices[t[1]] - p0).cross(mesh->vertices[t[2]] - p0);
        mesh->triangles.push_back(n.dot(out) > 0.0 ? t : std::array<int, 3>{t[0], t[2], t[1]});
      }
    }
  }
  return mesh;
}

}  // namespace sinew::testing

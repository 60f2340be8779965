#include <sinew/contact/smooth_collision_force.h>
#include <sinew/kinematics/body_depths.h>
#include <sinew/kinematics/forward_kinematics.h>
#include <sinew/kinematics/kinematic_tree.h>
#include <sinew/opensim/internal/collision_builder.h>
#include <sinew/opensim/internal/contact_mesh.h>
#include <sinew/opensim/support.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iterator>
#include <map>
#include <set>
#include <string_view>

namespace sinew::opensim::internal {

// The OpenSim contact geometry classes that collide (IsCollisionShapeClass).
constexpr std::string_view kCollisionShapeClasses[] = {
    "ContactHalfSpace", "ContactSphere", "ContactCylinder", "ContactEllipsoid", "ContactMesh"};

namespace {

// The contact geometry names the file's simulated contact forces use (any text of theirs that
// is a geometry's name: ContactParameters' <geometry>, the smooth force's sockets).
std::set<std::string> GeometryUsedByForces(const model::ModelSpec& spec,
                                           const std::vector<std::string>& disabled_forces) {
  std::set<std::string> names, used;
  for (const model::ContactGeometrySpec& g : spec.contact_geometry) names.insert(g.name);
  std::function<void(const model::Element&)> scan = [&](const model::Element& e) {
    for (size_t start = 0; start < e.text.size();) {
      const size_t end = std::min(e.text.find(' ', start), e.text.size());
      std::string word = e.text.substr(start, end - start);
      if (const size_t slash = word.find_last_of('/'); slash != std::string::npos)
        word = word.substr(slash + 1);
      if (names.count(word)) used.insert(word);
      start = end + 1;
    }
    for (const model::Element& c : e.children) scan(c);
  };
  for (const model::ForceSpec& f : spec.forces) {
    const bool contact_force = f.type == "HuntCrossleyForce" ||
                               f.type == "ElasticFoundationForce" ||
                               f.type == "SmoothSphereHalfSpaceForce";
    const bool disabled =
        std::find(disabled_forces.begin(), disabled_forces.end(), f.name) != disabled_forces.end();
    if (contact_force && f.applies_force && !disabled && IsForceSimulated(f)) scan(f.element);
  }
  return used;
}

// The numbers of a geometry's property `key` (empty when it has none).
std::vector<double> Numbers(const model::ContactGeometrySpec& g, const char* key) {
  const auto it = g.dimensions.find(key);
  return it == g.dimensions.end() ? std::vector<double>{} : it->second;
}

// True when `body` is ground or joined to it through WeldJoints only (the environment).
bool FixedToGround(const model::ModelSpec& spec, int body) {
  for (size_t hops = 0; body != model::kGroundIndex; ++hops) {
    const auto joint =
        std::find_if(spec.joints.begin(), spec.joints.end(),
                     [&](const model::JointSpec& j) { return j.child_body == body; });
    if (joint == spec.joints.end() || joint->kind != model::JointType::kWeld ||
        hops > spec.joints.size())
      return false;
    body = joint->parent_body;
  }
  return true;
}

// The collision geometry of an OpenSim ContactHalfSpace, ContactSphere, ContactCylinder,
// ContactEllipsoid or ContactMesh, or nullopt (with a Report warning) for another class.
// Throws sinew::Error at the geometry's line for a size that is not positive or a mesh that
// cannot be read.
std::optional<contact::CollisionGeometry> MakeGeometry(
    const model::ModelSpec& spec, const model::ContactGeometrySpec& g,
    const std::vector<std::string>& geometry_dirs, Report& report) {
  contact::CollisionGeometry shape;
  shape.name = g.name;
  shape.body = g.body;
  shape.X_BS = g.X_BC;
  const std::string component = "/contactgeometryset/" + g.name;
  const auto fail = [&](const std::string& message) {
    throw Error({spec.file, g.where.line}, component, message);
  };
  const auto positive_radius = [&]() {
    const std::vector<double> radius = Numbers(g, "radius");
    if (radius.size() != 1 || !(radius[0] > 0.0) || !std::isfinite(radius[0]))
      fail(g.type + " needs a radius > 0");
    return radius[0];
  };
  if (g.type == "ContactHalfSpace") {
    shape.kind = contact::CollisionShapeKind::kHalfSpace;
  } else if (g.type == "ContactSphere") {
    shape.kind = contact::CollisionShapeKind::kSphere;
    shape.radius = positive_radius();
  } else if (g.type == "ContactCylinder") {
    // Simbody's cylinder is infinite along z; it collides over the length OpenSim draws it.
    shape.kind = contact::CollisionShapeKind::kCylinder;
    shape.radius = positive_radius();
    shape.half_length = contact::kContactCylinderHalfLength * shape.radius;
    report.AddWarning({g.where, component,
                       "ContactCylinder is infinite along its z axis in OpenSim; it collides as "
                       "a cylinder 4 radii long (as OpenSim draws it)"});
  } else if (g.type == "ContactEllipsoid") {
    shape.kind = contact::CollisionShapeKind::kEllipsoid;
    const std::vector<double> radii = Numbers(g, "radii");
    if (radii.size() != 3 || !std::all_of(radii.begin(), radii.end(),
                                          [](double r) { return r > 0.0 && std::isfinite(r); }))
      fail("ContactEllipsoid needs three radii > 0");
    shape.radii = Vec3(radii[0], radii[1], radii[2]);
  } else if (g.type == "ContactMesh") {
    // Its triangles exactly, concave or not, on ground or on a moving body.
    shape.kind = contact::CollisionShapeKind::kTriangleMesh;
    shape.mesh = ReadContactMesh(spec, g, geometry_dirs);
    shape.fixed_to_ground = FixedToGround(spec, g.body);
  } else {
    report.AddWarning({g.where, component,
                       g.type + " is not a collision shape (ContactHalfSpace, ContactSphere, "
                                "ContactCylinder, ContactEllipsoid and ContactMesh are): it does "
                                "not collide"});
    return std::nullopt;
  }
  return shape;
}

// Gives the shapes named by `settings.overrides` their materials (index into model.materials).
void AssignMaterials(const model::ModelSpec& spec, const CollisionSettings& settings,
                     contact::CollisionModel& model) {
  for (const auto& [name, material] : settings.overrides) {
    const int index = static_cast<int>(model.materials.size());
    model.materials.push_back(material);
    bool found = false;
    SourceLocation where{spec.file, 0};
    const int body = spec.FindBody(name);
    if (body != model::kNone) {
      where = spec.bodies[body].where;
      for (contact::CollisionCylinder& c : model.shapes) {
        if (c.body == body) c.material = index, found = true;
      }
    }
    for (contact::CollisionGeometry& g : model.geometry) {
      if (g.name == name || (body != model::kNone && g.body == body))
        g.material = index, found = true;
    }
    for (const model::ContactGeometrySpec& g : spec.contact_geometry) {
      if (g.name == name) where = g.where;
    }
    contact::CheckMaterial(material, where, name);
    if (!found && body == model::kNone) {
      throw Error(SourceLocation{spec.file, 0}, name,
                  "a contact material names no body, contact geometry or environment shape");
    }
  }
}

// Warns about each pair of triangle meshes that may touch where one collides as its convex
// hull (contact::MeshPairHull) and that hull is not the mesh itself.
void WarnAboutMeshPairs(const model::ModelSpec& spec, const contact::CollisionModel& model,
                        Report& report) {
  std::vector<const contact::CollisionGeometry*> meshes;
  std::vector<contact::MeshPairSide> sides;
  for (const contact::CollisionGeometry& g : model.geometry) {
    if (g.kind == contact::CollisionShapeKind::kTriangleMesh && g.mesh) meshes.push_back(&g);
  }
  if (meshes.size() < 2) return;  // IsClosedConvex takes triangles times vertices
  for (const contact::CollisionGeometry* g : meshes) {
    sides.push_back(
        {g->body != model::kGroundIndex && !g->fixed_to_ground, contact::IsClosedConvex(*g->mesh)});
  }
  for (size_t i = 0; i < meshes.size(); ++i) {
    for (size_t j = i + 1; j < meshes.size(); ++j) {
      if (!model.CanCollide(meshes[i]->body, meshes[j]->body)) continue;
      const int side = contact::MeshPairHull(sides[i], sides[j]);
      if (side < 0 || sides[side == 0 ? i : j].closed_convex) continue;
      const contact::CollisionGeometry& hull = *meshes[side == 0 ? i : j];
      const contact::CollisionGeometry& other = *meshes[side == 0 ? j : i];
      SourceLocation where{spec.file, 0};
      for (const model::ContactGeometrySpec& g : spec.contact_geometry) {
        if (g.name == hull.name) where = g.where;
      }
      report.AddWarning({where, "/contactgeometryset/" + hull.name,
                         "against the ContactMesh '" + other.name +
                             "' it collides as its convex hull (a concave or open mesh is "
                             "filled in): mesh against mesh is not tested triangle by triangle"});
    }
  }
}

}  // namespace

contact::CollisionModel BuildCollision(const model::ModelSpec& spec,
                                       const CollisionSettings& settings,
                                       const std::vector<std::string>& disabled_forces,
                                       const std::vector<std::string>& geometry_dirs,
                                       Report& report) {
  contact::CheckMaterial(settings.material, {spec.file, 0}, "default contact material");
  contact::CollisionModel model = contact::BuildCollisionModel(
      spec, kinematics::CalcBodyDepths(spec), settings.family_1, settings.family_2);
  model.materials = {settings.material};
  const std::set<std::string> used = GeometryUsedByForces(spec, disabled_forces);
  for (const model::ContactGeometrySpec& g : spec.contact_geometry) {
    if (used.count(g.name)) {
      report.AddWarning({g.where, "/contactgeometryset/" + g.name,
                         "used by a contact force of the file, which handles its contacts: not "
                         "also a collision shape"});
      continue;
    }
    if (std::optional<contact::CollisionGeometry> shape =
            MakeGeometry(spec, g, geometry_dirs, report))
      model.geometry.push_back(*shape);
  }
  if (settings.ground_plane) contact::AddGroundPlane(model, *settings.ground_plane);
  for (const contact::CollisionGeometry& g : settings.environment) model.geometry.push_back(g);
  AssignMaterials(spec, settings, model);
  WarnAboutMeshPairs(spec, model, report);
  return model;
}

bool HasTangentialStiffness(const contact::CollisionModel& model) {
  return std::any_of(model.materials.begin(), model.materials.end(),
                     [](const contact::CollisionMaterial& m) { return m.kt > 0.0; });
}

std::vector<std::string> SmcOnlyParametersSet(const contact::CollisionModel& model) {
  const contact::CollisionMaterial d;
  std::vector<std::string> set;
  for (const auto& [name, field] :
       {std::pair{"young_modulus", &contact::CollisionMaterial::young_modulus},
        {"poisson_ratio", &contact::CollisionMaterial::poisson_ratio},
        {"kn", &contact::CollisionMaterial::kn},
        {"gn", &contact::CollisionMaterial::gn},
        {"kt", &contact::CollisionMaterial::kt},
        {"gt", &contact::CollisionMaterial::gt}}) {
    const auto member = field;  // (clang 14 cannot capture a structured binding)
    if (std::any_of(model.materials.begin(), model.materials.end(),
                    [&](const contact::CollisionMaterial& m) { return m.*member != d.*member; })) {
      set.push_back(name);
    }
  }
  return set;
}

void AddSmoothContact(engine::System& system, const model::ModelSpec& spec,
                      const contact::CollisionModel& model, const std::vector<int>& body_map,
                      double slip_speed, Report& report) {
  // The model in engine body indices.
  contact::CollisionModel mapped = model;
  for (contact::CollisionCylinder& c : mapped.shapes) c.body = body_map[c.body];
  for (contact::CollisionGeometry& g : mapped.geometry) g.body = body_map[g.body];
  for (auto& [a, b] : mapped.jointed) a = body_map[a], b = body_map[b];
  std::vector<int> family(system.num_bodies(), 0);
  for (size_t b = 0; b < model.family.size(); ++b) family[body_map[b]] = model.family[b];
  mapped.family = family;
  // Rest poses: the model's default pose.
  kinematics::KinematicTree tree(spec);
  std::vector<Transform> X_GB_spec(spec.bodies.size());
  kinematics::CalcBodyPoses(tree, tree.default_q(), X_GB_spec);
  std::vector<Transform> X_GB_rest(system.num_bodies());
  for (size_t b = 0; b < X_GB_spec.size(); ++b) X_GB_rest[body_map[b]] = X_GB_spec[b];
  auto detector = std::make_shared<contact::CollisionDetector>(mapped, std::nullopt, X_GB_rest);
  if (detector->num_excluded_at_rest() > 0) {
    report.AddWarning({SourceLocation{spec.file, 0}, "smc_contact",
                       std::to_string(detector->num_excluded_at_rest()) +
                           " shape pair(s) overlap in the default pose and never collide"});
  }
  std::vector<double> masses;
  for (const engine::Body& b : system.bodies()) masses.push_back(b.mass);
  // Reported: every body with a shape, ground included; every body pair that may touch.
  std::set<int> bodies;
  for (const auto& [a, b] : detector->BodyPairs()) bodies.insert(a), bodies.insert(b);
  std::vector<contact::ContactForce::RecordGroup> groups;
  for (int b : bodies) groups.push_back({system.bodies()[b].name, b});
  std::vector<contact::ContactForce::PairGroup> pairs;
  for (const auto& [a, b] : detector->BodyPairs())
    pairs.push_back({system.bodies()[a].name + "-" + system.bodies()[b].name, a, b});
  system.AddForceElement(std::make_shared<contact::SmoothCollisionForce>(
      "smc_contact", std::move(detector), std::move(masses), slip_speed, std::move(groups),
      std::move(pairs), HasTangentialStiffness(model)));
}

}  // namespace sinew::opensim::internal

namespace sinew::opensim {

bool IsCollisionShapeClass(std::string_view opensim_class) {
  return std::find(std::begin(internal::kCollisionShapeClasses),
                   std::end(internal::kCollisionShapeClasses),
                   opensim_class) != std::end(internal::kCollisionShapeClasses);
}

}  // namespace sinew::opensim

// Builders of OpenSim's contact forces (HuntCrossleyForce, ElasticFoundationForce,
// SmoothSphereHalfSpaceForce): their parameters and the contact geometry they name, checked,
// turned into contact::ContactShape and the contact layer's force elements.
#include <sinew/contact/elastic_foundation_force.h>
#include <sinew/contact/hunt_crossley_force.h>
#include <sinew/contact/smooth_sphere_half_space_force.h>
#include <sinew/model/element_values.h>
#include <sinew/model/force_source.h>
#include <sinew/opensim/internal/contact_mesh.h>
#include <sinew/opensim/internal/force_registry.h>

#include <map>
#include <sstream>

namespace sinew::opensim::internal {
namespace {

[[noreturn]] void FailAtGeometry(const model::ModelSpec& spec, const model::ContactGeometrySpec& g,
                                 const std::string& message) {
  throw Error({spec.file, g.where.line}, "/contactgeometryset/" + g.name, message);
}

// The contact geometry named `name` (a name or a path ending in one); fails naming the force.
const model::ContactGeometrySpec& FindGeometry(const ForceBuildInput& in,
                                               const model::ElementValues& values,
                                               const std::string& name, int line) {
  const std::string wanted = LastPathSegment(name);
  for (const model::ContactGeometrySpec& g : in.spec.contact_geometry) {
    if (g.name == wanted) return g;
  }
  values.Fail("names contact geometry '" + name +
                  "', which the model's ContactGeometrySet "
                  "does not have",
              line);
}

// The shape of a geometry: its kind, body (engine index), pose and size; fails at the
// geometry's line for a kind the contact forces do not handle or a radius that is not positive.
contact::ContactShape MakeShape(const ForceBuildInput& in, const model::ContactGeometrySpec& g) {
  contact::ContactShape shape;
  shape.name = g.name;
  shape.body = in.body_map[g.body];
  shape.X_BC = g.X_BC;
  if (g.type == "ContactHalfSpace") {
    shape.kind = contact::ShapeKind::kHalfSpace;
  } else if (g.type == "ContactSphere") {
    shape.kind = contact::ShapeKind::kSphere;
    const auto radius = g.dimensions.find("radius");
    shape.radius =
        radius == g.dimensions.end() || radius->second.size() != 1 ? 0.0 : radius->second[0];
    if (!(shape.radius > 0.0)) FailAtGeometry(in.spec, g, "ContactSphere needs a radius > 0");
  } else if (g.type == "ContactMesh") {
    shape.kind = contact::ShapeKind::kMesh;
    shape.mesh = ReadContactMesh(in.spec, g,
                                 in.geometry_dirs ? *in.geometry_dirs : std::vector<std::string>{});
  } else {
    FailAtGeometry(in.spec, g,
                   g.type +
                       " is not a contact geometry Sinew's contact forces handle (they take "
                       "ContactHalfSpace, ContactSphere and, for ElasticFoundationForce, "
                       "ContactMesh)");
  }
  return shape;
}

// A number property that must be >= 0 (> 0 when `positive`); fails at its line.
double NonNegative(const model::ElementValues& v, const model::Element& element, const char* tag,
                   double fallback, bool positive = false) {
  const double value = v.Double(tag, fallback);
  if (value < 0.0 || (positive && value == 0.0)) {
    const model::Element* property = element.Child(tag);
    std::ostringstream message;
    message << tag << " is " << value << "; it must be " << (positive ? "> 0" : ">= 0");
    v.Fail(message.str(), property ? property->line : 0);
  }
  return value;
}

// A set of shapes with their materials, in the order the ContactParametersSet lists them.
struct ContactSet {
  std::vector<contact::ContactShape> shapes;
  std::vector<contact::ContactMaterial> materials;
  std::vector<contact::ContactForce::RecordGroup> groups;
};

// The children of the force's ContactParametersSet (4.x and 3.x both write it as
// <Class::ContactParametersSet>, 4.x with name="contact_parameters").
std::vector<const model::Element*> ContactParameters(const model::Element& force) {
  std::vector<const model::Element*> out;
  for (const model::Element& child : force.children) {
    if (!child.tag.ends_with("ContactParametersSet") && child.tag != "contact_parameters") continue;
    const model::Element* objects = child.Child("objects");
    if (!objects) continue;
    for (const model::Element& p : objects->children) {
      if (p.tag.ends_with("ContactParameters")) out.push_back(&p);
    }
  }
  return out;
}

ContactSet ReadContactSet(const ForceBuildInput& in) {
  ContactSet set;
  const std::string& file = model::SourceFile(in.spec, in.force);
  for (const model::Element* params : ContactParameters(in.force.element)) {
    const model::ElementValues v(*params, file, in.force.path);
    contact::ContactMaterial m;
    m.stiffness = NonNegative(v, *params, "stiffness", 0.0);
    m.dissipation = NonNegative(v, *params, "dissipation", 0.0);
    m.static_friction = NonNegative(v, *params, "static_friction", 0.0);
    m.dynamic_friction = NonNegative(v, *params, "dynamic_friction", 0.0);
    m.viscous_friction = NonNegative(v, *params, "viscous_friction", 0.0);
    const model::Element* geometry = params->Child("geometry");
    std::istringstream names(geometry ? geometry->text : "");
    for (std::string name; names >> name;) {
      const model::ContactGeometrySpec& g =
          FindGeometry(in, v, name, geometry ? geometry->line : params->line);
      set.shapes.push_back(MakeShape(in, g));
      set.materials.push_back(m);
      set.groups.push_back(
          {g.frame.empty() ? in.spec.bodies[g.body].name : LastPathSegment(g.frame),
           set.shapes.back().body});
    }
  }
  if (set.shapes.empty()) in.values.Fail("names no contact geometry in its contact parameters");
  return set;
}

}  // namespace

std::shared_ptr<engine::ForceElement> BuildHuntCrossleyForce(const ForceBuildInput& in) {
  ContactSet set = ReadContactSet(in);
  for (const contact::ContactShape& s : set.shapes) {
    if (s.kind == contact::ShapeKind::kMesh) {
      in.values.Fail("contact geometry '" + s.name +
                     "' is a ContactMesh: HuntCrossleyForce acts "
                     "between spheres and half-spaces only (Simbody ignores meshes there; use "
                     "ElasticFoundationForce)");
    }
  }
  const double transition =
      NonNegative(in.values, in.force.element, "transition_velocity", 0.01, true);
  return std::make_shared<contact::HuntCrossleyForce>(in.force.name, std::move(set.shapes),
                                                      std::move(set.materials), transition,
                                                      std::move(set.groups));
}

std::shared_ptr<engine::ForceElement> BuildElasticFoundationForce(const ForceBuildInput& in) {
  ContactSet set = ReadContactSet(in);
  int meshes = 0;
  for (size_t i = 0; i < set.shapes.size(); ++i) {
    if (set.shapes[i].kind != contact::ShapeKind::kMesh) continue;
    ++meshes;
    for (size_t j = 0; j < i; ++j) {
      if (set.shapes[j].kind == contact::ShapeKind::kMesh &&
          set.shapes[j].body != set.shapes[i].body)
        in.values.Fail("meshes '" + set.shapes[j].name + "' and '" + set.shapes[i].name +
                       "' would touch each other: mesh-to-mesh elastic foundation contact is not "
                       "simulated yet");
    }
  }
  if (meshes == 0) {
    in.values.Fail(
        "names no ContactMesh: an ElasticFoundationForce acts only through the springs "
        "of its meshes (OpenSim applies no force here either)");
  }
  const double transition =
      NonNegative(in.values, in.force.element, "transition_velocity", 0.01, true);
  return std::make_shared<contact::ElasticFoundationForce>(in.force.name, std::move(set.shapes),
                                                           std::move(set.materials), transition,
                                                           std::move(set.groups));
}

std::shared_ptr<engine::ForceElement> BuildSmoothSphereHalfSpaceForce(const ForceBuildInput& in) {
  const model::ElementValues& v = in.values;
  const model::Element& e = in.force.element;
  auto socket = [&](const char* tag, contact::ShapeKind kind, const char* type) {
    const model::Element* property = e.Child(tag);
    if (!property) v.Fail(std::string("has no <") + tag + ">");
    contact::ContactShape shape =
        MakeShape(in, FindGeometry(in, v, property->text, property->line));
    if (shape.kind != kind) {
      v.Fail(std::string(tag) + " '" + property->text + "' must be a " + type, property->line);
    }
    return shape;
  };
  contact::ContactShape sphere =
      socket("socket_sphere", contact::ShapeKind::kSphere, "ContactSphere");
  contact::ContactShape half_space =
      socket("socket_half_space", contact::ShapeKind::kHalfSpace, "ContactHalfSpace");
  contact::SmoothContactParameters p;
  p.stiffness = NonNegative(v, e, "stiffness", p.stiffness);
  p.dissipation = NonNegative(v, e, "dissipation", p.dissipation);
  p.static_friction = NonNegative(v, e, "static_friction", p.static_friction);
  p.dynamic_friction = NonNegative(v, e, "dynamic_friction", p.dynamic_friction);
  p.viscous_friction = NonNegative(v, e, "viscous_friction", p.viscous_friction);
  p.transition_velocity = NonNegative(v, e, "transition_velocity", p.transition_velocity, true);
  p.constant_contact_force = NonNegative(v, e, "constant_contact_force", p.constant_contact_force);
  p.hertz_smoothing = NonNegative(v, e, "hertz_smoothing", p.hertz_smoothing);
  p.hunt_crossley_smoothing =
      NonNegative(v, e, "hunt_crossley_smoothing", p.hunt_crossley_smoothing);
  return std::make_shared<contact::SmoothSphereHalfSpaceForce>(in.force.name, std::move(sphere),
                                                               std::move(half_space), p);
}

}  // namespace sinew::opensim::internal

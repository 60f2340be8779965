#include <sinew/kinematics/joint_model.h>
#include <sinew/opensim/internal/constraint_registry.h>
#include <sinew/opensim/internal/force_registry.h>
#include <sinew/opensim/support.h>
#include <sinew/paths/wrap_surface_factory.h>

#include <algorithm>
#include <array>
#include <sstream>
#include <string>

namespace sinew::opensim {

bool IsJointSimulated(const model::JointSpec& joint) {
  return kinematics::IsJointTypeModeled(joint.kind);
}
bool IsForceSimulated(const model::ForceSpec& force) {
  return force.applies_force && internal::FindForceType(force.type) != nullptr;
}
bool IsConstraintSimulated(const model::ConstraintSpec& constraint) {
  return constraint.enabled && internal::FindConstraintType(constraint.type) != nullptr;
}
bool IsControllerSimulated(const model::ControllerSpec& controller) {
  return controller.type == "PrescribedController";
}
namespace {
// True when `element` or one of its descendants names geometry `name` (a `geometry` list of
// contact parameters, or a socket path such as socket_sphere).
bool NamesGeometry(const model::Element& element, const std::string& name) {
  if (element.tag == "geometry" || element.tag.starts_with("socket_")) {
    std::istringstream names(element.text);
    for (std::string n; names >> n;) {
      const size_t slash = n.find_last_of('/');
      if ((slash == std::string::npos ? n : n.substr(slash + 1)) == name) return true;
    }
  }
  for (const model::Element& child : element.children) {
    if (NamesGeometry(child, name)) return true;
  }
  return false;
}
}  // namespace

bool IsContactGeometrySimulated(const model::ModelSpec& spec,
                                const model::ContactGeometrySpec& contact) {
  for (const model::ForceSpec& f : spec.forces) {
    if (IsForceSimulated(f) && NamesGeometry(f.element, contact.name)) return true;
  }
  return false;
}
bool IsWrapObjectSimulated(const model::WrapObjectSpec& wrap) {
  return paths::IsWrapSurfaceSupported(wrap.type);
}

std::vector<NotSimulatedElement> FindNotSimulated(const model::ModelSpec& spec,
                                                  const std::vector<std::string>& disabled_forces) {
  std::vector<NotSimulatedElement> out;
  for (const model::JointSpec& j : spec.joints) {
    if (!IsJointSimulated(j)) out.push_back({ElementKind::kJoint, j.path, j.type});
  }
  for (const model::ForceSpec& f : spec.forces) {
    // A force the file switches off (appliesForce false) is off in OpenSim too: nothing is left
    // out. The parser's Report lists it as disabled.
    if (IsForceSimulated(f) || !f.applies_force) continue;
    if (std::find(disabled_forces.begin(), disabled_forces.end(), f.name) != disabled_forces.end())
      continue;
    const bool muscle = f.type.ends_with("Muscle");
    out.push_back({muscle ? ElementKind::kMuscle : ElementKind::kForce, f.path, f.type});
  }
  for (const model::ConstraintSpec& c : spec.constraints) {
    if (!IsConstraintSimulated(c)) out.push_back({ElementKind::kConstraint, c.path, c.type});
  }
  for (const model::ControllerSpec& c : spec.controllers) {
    if (!IsControllerSimulated(c)) {
      out.push_back({ElementKind::kController, "/controllerset/" + c.name, c.type});
    }
  }
  for (const model::ContactGeometrySpec& c : spec.contact_geometry) {
    if (!IsContactGeometrySimulated(spec, c)) {
      out.push_back({ElementKind::kContactGeometry, "/contactgeometryset/" + c.name, c.type});
    }
  }
  for (const model::BodySpec& b : spec.bodies) {
    for (const model::WrapObjectSpec& w : b.wrap_objects) {
      if (!IsWrapObjectSimulated(w)) {
        out.push_back({ElementKind::kWrapObject, b.path + "/wrapobjectset/" + w.name, w.type});
      }
    }
  }
  for (const model::Element& e : spec.other_components) {
    out.push_back({ElementKind::kOther, "/" + (e.name.empty() ? e.tag : e.name), e.tag});
  }
  return out;
}

std::vector<std::string> ListNotSimulated(const model::ModelSpec& spec,
                                          const std::vector<std::string>& disabled_forces) {
  std::vector<std::string> lines;
  for (const NotSimulatedElement& e : FindNotSimulated(spec, disabled_forces))
    lines.push_back(e.path + ": " + e.type);
  return lines;
}

std::string CountByKind(const std::vector<NotSimulatedElement>& elements) {
  constexpr int kKinds = static_cast<int>(ElementKind::kOther) + 1;
  std::array<int, kKinds> counts{};
  for (const NotSimulatedElement& e : elements) ++counts[static_cast<int>(e.kind)];
  const bool muscles = counts[static_cast<int>(ElementKind::kMuscle)] > 0;
  // Singular and plural names, in ElementKind order.
  const std::array<std::array<const char*, 2>, kKinds> names = {{
      {"joint", "joints"},
      {"muscle", "muscles"},
      {muscles ? "other force" : "force", muscles ? "other forces" : "forces"},
      {"constraint", "constraints"},
      {"controller", "controllers"},
      {"contact geometry", "contact geometries"},
      {"wrap object", "wrap objects"},
      {"other component", "other components"},
  }};
  std::vector<std::string> parts;
  for (int k = 0; k < kKinds; ++k) {
    if (counts[k] > 0) {
      parts.push_back(std::to_string(counts[k]) + " " + names[k][counts[k] == 1 ? 0 : 1]);
    }
  }
  std::string text;
  for (size_t i = 0; i < parts.size(); ++i) {
    if (i > 0) text += i + 1 == parts.size() ? " and " : ", ";
    text += parts[i];
  }
  return text;
}

std::vector<StandIn> ReplaceWithStandIns(model::ModelSpec& spec) {
  std::vector<StandIn> replaced;
  for (size_t j = 0; j < spec.joints.size(); ++j) {
    model::JointSpec& joint = spec.joints[j];
    if (IsJointSimulated(joint)) continue;
    StandIn standin{static_cast<int>(j), joint.coordinates};
    for (int c : joint.coordinates) spec.coordinates[c].joint = model::kNone;
    joint.kind = model::JointType::kBall;
    joint.coordinates.clear();
    joint.spatial_transform.clear();
    for (const char* axis : {"x", "y", "z"}) {
      model::CoordinateSpec c;
      c.name = joint.name + "_standin_r" + axis;
      c.path = joint.path + "/" + c.name;
      c.joint = static_cast<int>(j);
      c.where = joint.where;
      joint.coordinates.push_back(static_cast<int>(spec.coordinates.size()));
      spec.coordinates.push_back(std::move(c));
    }
    replaced.push_back(std::move(standin));
  }
  return replaced;
}

}  // namespace sinew::opensim

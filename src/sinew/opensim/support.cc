#include <sinew/opensim/support.h>

#include <sinew/opensim/internal/actuator_builder.h>

namespace sinew::opensim {

bool IsJointSimulated(const model::JointSpec& joint) {
  return joint.kind != model::JointType::kUnknown;
}
bool IsForceSimulated(const model::ForceSpec& force) {
  return force.applies_force && internal::IsIdealActuator(force.type);
}
bool IsConstraintSimulated(const model::ConstraintSpec& /*constraint*/) { return false; }
bool IsControllerSimulated(const model::ControllerSpec& controller) {
  return controller.type == "PrescribedController";
}
bool IsContactGeometrySimulated(const model::ContactGeometrySpec& /*contact*/) { return false; }
bool IsWrapObjectSimulated(const model::WrapObjectSpec& /*wrap*/) { return false; }

std::vector<std::string> ListNotSimulated(const model::ModelSpec& spec) {
  std::vector<std::string> lines;
  for (const model::JointSpec& j : spec.joints) {
    if (!IsJointSimulated(j)) lines.push_back(j.path + ": " + j.type);
  }
  for (const model::ForceSpec& f : spec.forces) {
    if (!IsForceSimulated(f)) lines.push_back(f.path + ": " + f.type);
  }
  for (const model::ConstraintSpec& c : spec.constraints) {
    if (!IsConstraintSimulated(c)) lines.push_back(c.path + ": " + c.type);
  }
  for (const model::ControllerSpec& c : spec.controllers) {
    if (!IsControllerSimulated(c)) lines.push_back("/controllerset/" + c.name + ": " + c.type);
  }
  for (const model::ContactGeometrySpec& c : spec.contact_geometry) {
    if (!IsContactGeometrySimulated(c)) {
      lines.push_back("/contactgeometryset/" + c.name + ": " + c.type);
    }
  }
  for (const model::BodySpec& b : spec.bodies) {
    for (const model::WrapObjectSpec& w : b.wrap_objects) {
      if (!IsWrapObjectSimulated(w)) {
        lines.push_back(b.path + "/wrapobjectset/" + w.name + ": " + w.type);
      }
    }
  }
  for (const model::Element& e : spec.other_components) {
    lines.push_back("/" + (e.name.empty() ? e.tag : e.name) + ": " + e.tag);
  }
  return lines;
}

}  // namespace sinew::opensim

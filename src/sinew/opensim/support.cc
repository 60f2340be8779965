#include <sinew/opensim/support.h>

#include <sinew/opensim/internal/actuator_builder.h>

namespace sinew {

bool IsJointSimulated(const JointSpec& joint) { return joint.kind != JointType::kUnknown; }
bool IsForceSimulated(const ForceSpec& force) {
  return force.applies_force && IsIdealActuator(force.type);
}
bool IsConstraintSimulated(const ConstraintSpec& /*constraint*/) { return false; }
bool IsControllerSimulated(const ControllerSpec& controller) {
  return controller.type == "PrescribedController";
}
bool IsContactGeometrySimulated(const ContactGeometrySpec& /*contact*/) { return false; }
bool IsWrapObjectSimulated(const WrapObjectSpec& /*wrap*/) { return false; }

std::vector<std::string> ListNotSimulated(const ModelSpec& spec) {
  std::vector<std::string> lines;
  for (const JointSpec& j : spec.joints) {
    if (!IsJointSimulated(j)) lines.push_back(j.path + ": " + j.type);
  }
  for (const ForceSpec& f : spec.forces) {
    if (!IsForceSimulated(f)) lines.push_back(f.path + ": " + f.type);
  }
  for (const ConstraintSpec& c : spec.constraints) {
    if (!IsConstraintSimulated(c)) lines.push_back(c.path + ": " + c.type);
  }
  for (const ControllerSpec& c : spec.controllers) {
    if (!IsControllerSimulated(c)) lines.push_back("/controllerset/" + c.name + ": " + c.type);
  }
  for (const ContactGeometrySpec& c : spec.contact_geometry) {
    if (!IsContactGeometrySimulated(c)) {
      lines.push_back("/contactgeometryset/" + c.name + ": " + c.type);
    }
  }
  for (const BodySpec& b : spec.bodies) {
    for (const WrapObjectSpec& w : b.wrap_objects) {
      if (!IsWrapObjectSimulated(w)) {
        lines.push_back(b.path + "/wrapobjectset/" + w.name + ": " + w.type);
      }
    }
  }
  for (const Element& e : spec.other_components) {
    lines.push_back("/" + (e.name.empty() ? e.tag : e.name) + ": " + e.tag);
  }
  return lines;
}

}  // namespace sinew

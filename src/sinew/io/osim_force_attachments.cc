// What some force classes need beyond their plain properties: the frames their sockets name
// (resolved to a body and an offset in it) and their function-valued properties.
#include <sinew/io/internal/osim_context.h>
#include <sinew/io/internal/read_function.h>

#include <map>
#include <string_view>
#include <vector>

namespace sinew::io::internal {
namespace {

// The frame of socket `socket_tag` (4.x, relative to the force) or, in a 3.x file, of the body
// named by `body_tag` offset by `location_tag`/`orientation_tag` (OpenSim's TwoFrameLinker
// upgrade makes that offset a PhysicalOffsetFrame on the body). Absent tags: no frame.
void ReadSocketFrame(ReadContext& ctx, const pugi::xml_node& node, model::ForceSpec& force,
                     const std::string& socket_name, const char* socket_tag, const char* body_tag,
                     const char* location_tag, const char* orientation_tag) {
  const XmlDocument& doc = ctx.doc();
  const FrameEntry* frame = nullptr;
  model::ForceFrameSpec resolved;
  if (pugi::xml_node socket = node.child(socket_tag)) {
    resolved.path =
        ctx.ResolveFrame(force.path, XmlDocument::Text(socket), socket, force.path, &frame);
    resolved.body = frame->body;
    resolved.X_BF = frame->X_BF;
  } else if (pugi::xml_node body = body_tag ? node.child(body_tag) : pugi::xml_node()) {
    const std::string_view name = XmlDocument::Text(body);
    const std::string body_path = name == "ground" ? "/ground" : "/bodyset/" + std::string(name);
    if (name.empty() || !ctx.HasFrame(body_path)) {
      doc.Fail(body, force.path,
               "<" + std::string(body_tag) + "> '" + std::string(name) + "' is not a body");
    }
    resolved.path = ctx.ResolveFrame("", body_path, body, force.path, &frame);
    resolved.body = frame->body;
    const Transform offset =
        MakeTransform(ReadVec3Or(doc, node, orientation_tag, force.path, Vec3::Zero()),
                      ReadVec3Or(doc, node, location_tag, force.path, Vec3::Zero()));
    resolved.X_BF = frame->X_BF * offset;
  } else {
    return;
  }
  force.frames[socket_name] = resolved;
}

// Function-valued properties read for the classes whose builders use them.
const std::map<std::string_view, std::vector<std::string>>& FunctionProperties() {
  // OpenSim reads a file's Schutte1993Muscle as Schutte1993Muscle_Deprecated.
  const std::vector<std::string> kSchutteCurves = {
      "tendon_force_length_curve", "active_force_length_curve", "passive_force_length_curve"};
  static const std::map<std::string_view, std::vector<std::string>> properties = {
      {"FunctionBasedBushingForce",
       {"m_x_theta_x_function", "m_y_theta_y_function", "m_z_theta_z_function",
        "f_x_delta_x_function", "f_y_delta_y_function", "f_z_delta_z_function"}},
      {"Schutte1993Muscle_Deprecated", kSchutteCurves},
      {"Schutte1993Muscle", kSchutteCurves},
      {"RigidTendonMuscle",
       {"active_force_length_curve", "passive_force_length_curve", "force_velocity_curve"}},
  };
  return properties;
}

// FunctionSet-valued properties: 4.x `<forceFunctions><objects>...` or 3.x
// `<FunctionSet name="forceFunctions"><objects>...`.
const std::map<std::string_view, std::vector<std::string>>& FunctionSetProperties() {
  static const std::map<std::string_view, std::vector<std::string>> properties = {
      {"PrescribedForce", {"forceFunctions", "pointFunctions", "torqueFunctions"}},
  };
  return properties;
}

pugi::xml_node FindFunctionSet(const pugi::xml_node& node, const std::string& property) {
  if (pugi::xml_node set = node.child(property.c_str())) return set;
  for (pugi::xml_node set : node.children("FunctionSet")) {
    if (NameOf(set) == property) return set;
  }
  return {};
}

}  // namespace

void ReadForceAttachments(ReadContext& ctx, const pugi::xml_node& node, model::ForceSpec& force) {
  const XmlDocument& doc = ctx.doc();
  ReadSocketFrame(ctx, node, force, "frame1", "socket_frame1", "body_1", "location_body_1",
                  "orientation_body_1");
  ReadSocketFrame(ctx, node, force, "frame2", "socket_frame2", "body_2", "location_body_2",
                  "orientation_body_2");
  ReadSocketFrame(ctx, node, force, "frame", "socket_frame", nullptr, nullptr, nullptr);
  if (auto it = FunctionProperties().find(force.type); it != FunctionProperties().end()) {
    for (const std::string& property : it->second) {
      if (functions::FunctionPtr f = ReadFunctionProperty(doc, node, property, force.path)) {
        force.functions[property] = {f};
      }
    }
  }
  if (auto it = FunctionSetProperties().find(force.type); it != FunctionSetProperties().end()) {
    for (const std::string& property : it->second) {
      std::vector<functions::FunctionPtr>& members = force.functions[property];
      for (pugi::xml_node f : ObjectsOf(FindFunctionSet(node, property))) {
        members.push_back(ReadFunction(doc, f, force.path));
      }
    }
  }
}

}  // namespace sinew::io::internal

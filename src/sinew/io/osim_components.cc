// Constraints, markers, contact geometry, controllers, and everything else a model lists (probes,
// components): typed common fields plus the full element tree.
#include <sinew/io/internal/osim_context.h>
#include <sinew/io/internal/read_function.h>

#include <sstream>
#include <string_view>

namespace sinew::io::internal {
namespace {

// The frame named by a 4.x socket (relative to `own_path`) or a 3.x body name.
const FrameEntry* Attachment(ReadContext& ctx, const pugi::xml_node& node,
                             const std::string& own_path, const char* socket_tag,
                             const char* body_tag, std::string* frame_path) {
  const FrameEntry* frame = nullptr;
  if (pugi::xml_node socket = node.child(socket_tag)) {
    *frame_path = ctx.ResolveFrame(own_path, XmlDocument::Text(socket), socket, own_path, &frame);
    return frame;
  }
  if (pugi::xml_node body = node.child(body_tag)) {
    const std::string_view name = XmlDocument::Text(body);
    const std::string path = name == "ground" ? "/ground" : "/bodyset/" + std::string(name);
    if (name.empty() || !ctx.HasFrame(path)) {
      ctx.doc().Fail(body, own_path,
                     "<" + std::string(body_tag) + "> '" + std::string(name) + "' does not exist");
    }
    *frame_path = ctx.ResolveFrame("", path, body, own_path, &frame);
    return frame;
  }
  ctx.doc().Fail(node, own_path,
                 "names no frame (<" + std::string(socket_tag) + "> or <" + body_tag + ">)");
}

// The sockets (4.x) and body properties (3.x) that name a body-to-body constraint's two
// frames, by OpenSim class.
struct ConstraintFrameTags {
  const char* socket[2];
  const char* body[2];
};

const ConstraintFrameTags* FindConstraintFrameTags(std::string_view type) {
  static const ConstraintFrameTags kWeld{{"socket_frame1", "socket_frame2"}, {"body_1", "body_2"}};
  static const ConstraintFrameTags kBodies{{"socket_body_1", "socket_body_2"},
                                           {"body_1", "body_2"}};
  static const ConstraintFrameTags kLine{{"socket_line_body", "socket_follower_body"},
                                         {"line_body", "follower_body"}};
  if (type == "WeldConstraint") return &kWeld;
  if (type == "PointConstraint" || type == "ConstantDistanceConstraint") return &kBodies;
  if (type == "PointOnLineConstraint") return &kLine;
  return nullptr;
}

// Resolves the two frames of a body-to-body constraint. A 3.x WeldConstraint places its frames
// with location_body_i and orientation_body_i in the bodies (OpenSim turns them into offset
// frames when it upgrades the file); the other types keep their points as properties.
void ReadConstraintFrames(ReadContext& ctx, const pugi::xml_node& node, model::ConstraintSpec& c) {
  const ConstraintFrameTags* tags = FindConstraintFrameTags(c.type);
  if (!tags) return;
  for (int i = 0; i < 2; ++i) {
    model::ConstraintFrame& frame = c.frames[i];
    const FrameEntry* entry =
        Attachment(ctx, node, c.path, tags->socket[i], tags->body[i], &frame.frame);
    frame.body = entry->body;
    frame.X_BF = entry->X_BF;
    if (c.type == "WeldConstraint" && !node.child(tags->socket[i])) {
      const std::string suffix = std::to_string(i + 1);
      const std::string location = "location_body_" + suffix;
      const std::string orientation = "orientation_body_" + suffix;
      frame.X_BF =
          frame.X_BF *
          MakeTransform(ReadVec3Or(ctx.doc(), node, orientation.c_str(), c.path, Vec3::Zero()),
                        ReadVec3Or(ctx.doc(), node, location.c_str(), c.path, Vec3::Zero()));
    }
  }
}

void ReadConstraints(ReadContext& ctx, const pugi::xml_node& model) {
  const XmlDocument& doc = ctx.doc();
  for (pugi::xml_node node : ObjectsOf(model.child("ConstraintSet"))) {
    model::ConstraintSpec c;
    c.name = NameOf(node);
    c.type = node.name();
    c.path = "/constraintset/" + c.name;
    c.enabled = ReadEnabledFlag(doc, node, "isEnforced", c.path, c.enabled);
    // CoordinateCouplerConstraint: the coordinates it couples must exist (and be unambiguous).
    for (const char* tag : {"dependent_coordinate_name", "independent_coordinate_names"}) {
      pugi::xml_node names = node.child(tag);
      std::istringstream list(names ? std::string(XmlDocument::Text(names)) : std::string());
      const bool dependent = std::string_view(tag) == "dependent_coordinate_name";
      std::string name;
      while (list >> name) {
        const int coordinate = ResolveCoordinateName(ctx, names, name, c.path);
        if (dependent) {
          c.dependent_coordinate = coordinate;
        } else {
          c.independent_coordinates.push_back(coordinate);
        }
      }
    }
    if (c.type == "CoordinateCouplerConstraint") {
      c.function = ReadFunctionProperty(doc, node, "coupled_coordinates_function", c.path);
      c.scale_factor = ReadDoubleOr(doc, node, "scale_factor", c.path, 1.0);
    }
    ReadConstraintFrames(ctx, node, c);
    c.element = ToElement(doc, node);
    c.where = doc.Where(node);
    ctx.spec().constraints.push_back(std::move(c));
  }
}

void ReadMarkers(ReadContext& ctx, const pugi::xml_node& model) {
  const XmlDocument& doc = ctx.doc();
  for (pugi::xml_node node : ObjectsOf(model.child("MarkerSet"))) {
    model::MarkerSpec marker;
    marker.name = NameOf(node);
    const std::string path = "/markerset/" + marker.name;
    const FrameEntry* frame =
        Attachment(ctx, node, path, "socket_parent_frame", "body", &marker.frame);
    marker.body = frame->body;
    marker.location = frame->X_BF * ReadVec3Or(doc, node, "location", path, Vec3::Zero());
    marker.fixed = ReadBoolOr(doc, node, "fixed", path, false);
    marker.where = doc.Where(node);
    ctx.spec().markers.push_back(std::move(marker));
  }
}

void ReadContactGeometry(ReadContext& ctx, const pugi::xml_node& model) {
  const XmlDocument& doc = ctx.doc();
  for (pugi::xml_node node : ObjectsOf(model.child("ContactGeometrySet"))) {
    model::ContactGeometrySpec c;
    c.name = NameOf(node);
    c.type = node.name();
    const std::string path = "/contactgeometryset/" + c.name;
    const FrameEntry* frame = Attachment(ctx, node, path, "socket_frame", "body_name", &c.frame);
    c.body = frame->body;
    c.X_BC = frame->X_BF * MakeTransform(ReadVec3Or(doc, node, "orientation", path, Vec3::Zero()),
                                         ReadVec3Or(doc, node, "location", path, Vec3::Zero()));
    c.dimensions = ReadNumericLeaves(doc, node, path, {"location", "orientation"});
    c.mesh_file = TextOf(node, "filename");
    c.element = ToElement(doc, node);
    c.where = doc.Where(node);
    ctx.spec().contact_geometry.push_back(std::move(c));
  }
}

// A PrescribedController's FunctionSet: one function per actuator, in actuator_list order.
void ReadControlFunctions(const XmlDocument& doc, const pugi::xml_node& node,
                          model::ControllerSpec& c) {
  const std::string path = "/controllerset/" + c.name;
  for (pugi::xml_node set : node.children("FunctionSet")) {
    for (pugi::xml_node f : set.child("objects").children()) {
      if (f.type() == pugi::node_element) c.functions.push_back(ReadFunction(doc, f, path));
    }
  }
  if (c.functions.size() != c.actuators.size()) {
    doc.Fail(node, path,
             std::to_string(c.actuators.size()) + " actuator(s) but " +
                 std::to_string(c.functions.size()) + " control function(s)");
  }
}

void ReadControllers(ReadContext& ctx, const pugi::xml_node& model) {
  const XmlDocument& doc = ctx.doc();
  for (pugi::xml_node node : ObjectsOf(model.child("ControllerSet"))) {
    model::ControllerSpec c;
    c.name = NameOf(node);
    c.type = node.name();
    std::string list = TextOf(node, "socket_actuators");
    if (list.empty()) list = TextOf(node, "actuator_list");
    std::istringstream names(list);
    std::string name;
    while (names >> name) c.actuators.push_back(name);
    if (c.type == "PrescribedController") ReadControlFunctions(doc, node, c);
    c.element = ToElement(doc, node);
    c.where = doc.Where(node);
    ctx.spec().controllers.push_back(std::move(c));
  }
}

// Model children the reader handles (or that carry no model content).
bool IsKnownModelChild(std::string_view tag) {
  static constexpr std::string_view kKnown[] = {"Ground",
                                                "BodySet",
                                                "JointSet",
                                                "ForceSet",
                                                "ConstraintSet",
                                                "MarkerSet",
                                                "ContactGeometrySet",
                                                "ControllerSet",
                                                "ProbeSet",
                                                "ComponentSet",
                                                "components",
                                                "FrameSet",
                                                "gravity",
                                                "credits",
                                                "publications",
                                                "length_units",
                                                "force_units",
                                                "defaults",
                                                "assembly_accuracy",
                                                "validationLog",
                                                "FrameGeometry",
                                                "socket_frame",
                                                "WrapObjectSet",
                                                "attached_geometry",
                                                "Appearance",
                                                "DynamicsEngine",
                                                "AnalysisSet",
                                                "frame_geometry",
                                                "ModelVisualPreferences"};
  for (std::string_view known : kKnown) {
    if (tag == known) return true;
  }
  return false;
}

}  // namespace

void ReadOtherComponents(ReadContext& ctx, const pugi::xml_node& model) {
  const XmlDocument& doc = ctx.doc();
  model::ModelSpec& spec = ctx.spec();
  ReadConstraints(ctx, model);
  ReadMarkers(ctx, model);
  ReadContactGeometry(ctx, model);
  ReadControllers(ctx, model);
  for (const char* tag : {"ProbeSet", "ComponentSet", "components"}) {
    for (pugi::xml_node node : ObjectsOf(model.child(tag))) {
      // Model-level offset frames are read as frames already.
      if (std::string_view(node.name()) == "PhysicalOffsetFrame") continue;
      spec.other_components.push_back(ToElement(doc, node));
    }
  }
  for (pugi::xml_node child : model.children()) {
    if (child.type() != pugi::node_element || IsKnownModelChild(child.name())) continue;
    ctx.Warn(child, "/",
             "unknown model property <" + std::string(child.name()) + "> kept, not used",
             std::string("model:") + child.name());
    spec.other_components.push_back(ToElement(doc, child));
  }
}

}  // namespace sinew::io::internal

// Ground, bodies (mass properties, geometry, wrap objects) and 4.x PhysicalOffsetFrames.
#include <sinew/io/internal/osim_context.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <sstream>
#include <string_view>

namespace sinew::io::internal {
namespace {

// Body properties the reader understands; anything else gets one warning per tag.
bool IsKnownBodyProperty(std::string_view tag) {
  static constexpr std::string_view kKnown[] = {
      "mass",           "mass_center",   "inertia",           "inertia_xx", "inertia_yy",
      "inertia_zz",     "inertia_xy",    "inertia_xz",        "inertia_yz", "Joint",
      "VisibleObject",  "WrapObjectSet", "attached_geometry", "components", "FrameGeometry",
      "frame_geometry", "socket_frame",  "Appearance"};
  for (std::string_view known : kKnown) {
    if (tag == known) return true;
  }
  return false;
}

std::string ShowMoments(const Vec3& moments) {
  std::ostringstream text;
  text << moments.x() << ", " << moments.y() << ", " << moments.z();
  return text.str();
}

// A physical inertia has moments >= 0 and is positive semi-definite, each principal moment at
// most the sum of the other two (the triangle inequality). A negative moment on the diagonal is
// an error: no rounding explains it, and the engine would divide by it. An indefinite matrix with
// a non-negative diagonal, and a triangle-inequality violation, are warnings: OpenSim accepts
// both and real models have them (ThoracoscapularShoulderModel's radius is indefinite,
// SoccerKickingModel's toes break the triangle). Tests allow for rounding, relative to the
// largest moment.
void CheckInertia(ReadContext& ctx, const pugi::xml_node& where, const std::string& component,
                  const Mat3& inertia) {
  const Eigen::SelfAdjointEigenSolver<Mat3> solver(inertia, Eigen::EigenvaluesOnly);
  const Vec3 moments = solver.eigenvalues();  // ascending
  const double tolerance = 1e-9 * moments.cwiseAbs().maxCoeff();
  if (inertia.diagonal().minCoeff() < 0) {
    ctx.doc().Fail(where, component,
                   "negative moment of inertia (the diagonal is " +
                       ShowMoments(inertia.diagonal()) +
                       "); moments of inertia cannot be negative");
  }
  if (moments[0] < -tolerance) {
    ctx.Warn(where, component,
             "indefinite inertia matrix (principal moments " + ShowMoments(moments) +
                 "): no rigid body has a negative principal moment; read as written, as OpenSim "
                 "does");
  } else if (moments[0] + moments[1] < moments[2] - tolerance) {
    ctx.Warn(where, component,
             "inertia violates the triangle inequality (principal moments " + ShowMoments(moments) +
                 ": the largest exceeds the sum of the other two); no rigid body has such an "
                 "inertia; read as written, as OpenSim does");
  }
}

// Inertia about the mass centre: `inertia` [Ixx Iyy Izz Ixy Ixz Iyz] or the older
// inertia_xx ... inertia_yz. Checked by CheckInertia.
Mat3 ReadInertia(ReadContext& ctx, const pugi::xml_node& body, const std::string& component) {
  const XmlDocument& doc = ctx.doc();
  double m[6] = {0, 0, 0, 0, 0, 0};
  pugi::xml_node where = body;
  if (pugi::xml_node node = body.child("inertia")) {
    std::vector<double> v = doc.ReadNumbers(node, component, 6);
    for (int i = 0; i < 6; ++i) m[i] = v[i];
    where = node;
  } else {
    const char* tags[6] = {"inertia_xx", "inertia_yy", "inertia_zz",
                           "inertia_xy", "inertia_xz", "inertia_yz"};
    for (int i = 0; i < 6; ++i) m[i] = ReadDoubleOr(doc, body, tags[i], component, 0.0);
    if (pugi::xml_node first = body.child("inertia_xx")) where = first;
  }
  Mat3 inertia;
  inertia << m[0], m[3], m[4], m[3], m[1], m[5], m[4], m[5], m[2];
  CheckInertia(ctx, where, component, inertia);
  return inertia;
}

// The obstacles' wrap directions are text, and a wrap object's spec keeps numbers: each is
// kept among the dimensions as `key`, +1 for right-handed (also when none is written,
// OpenSim's default) and -1 for left-handed, in any of OpenSim's spellings. `tag` is
// WrapCylinderObst's wrapDirection or WrapDoubleCylinderObst's wrapUcylDirection and
// wrapVcylDirection.
void ReadWrapDirection(const XmlDocument& doc, const pugi::xml_node& wrap,
                       const std::string& component, const char* tag, const std::string& key,
                       model::NumberMap& dimensions) {
  const std::string text = TextOf(wrap, tag);
  if (text.empty()) return;
  for (const char* right :
       {"righthand", "right", "righthanded", "Righthand", "Right", "Righthanded", "Unassigned"}) {
    if (text == right) dimensions[key] = {1.0};
  }
  for (const char* left : {"lefthand", "left", "lefthanded", "Lefthand", "Left", "Lefthanded"}) {
    if (text == left) dimensions[key] = {-1.0};
  }
  if (!dimensions.contains(key)) {
    doc.Fail(wrap.child(tag), component,
             std::string(tag) + " '" + text + "' is not righthand or lefthand");
  }
}

// WrapDoubleCylinderObst's V cylinder: the body named by wrapVcylHomeBodyName (OpenSim's
// default, "Unassigned", names none) and its frame there.
void ReadVCylinder(ReadContext& ctx, const pugi::xml_node& wrap, const std::string& component,
                   model::WrapObjectSpec& spec) {
  const XmlDocument& doc = ctx.doc();
  ReadWrapDirection(doc, wrap, component, "wrapUcylDirection", "wrap_ucyl_direction",
                    spec.dimensions);
  ReadWrapDirection(doc, wrap, component, "wrapVcylDirection", "wrap_vcyl_direction",
                    spec.dimensions);
  const std::string body = TextOf(wrap, "wrapVcylHomeBodyName");
  spec.second_body = body.empty() ? model::kNone : ctx.BodyIndex(body);
  if (spec.second_body == model::kNone) {
    const pugi::xml_node where = wrap.child("wrapVcylHomeBodyName");
    doc.Fail(where ? where : wrap, component,
             "WrapDoubleCylinderObst: wrapVcylHomeBodyName '" +
                 (body.empty() ? std::string("Unassigned") : body) +
                 "' is not a body of the model (the V cylinder needs one)");
  }
  spec.X_BV = MakeTransform(ReadVec3Or(doc, wrap, "xyz_body_rotationVcyl", component, Vec3::Zero()),
                            ReadVec3Or(doc, wrap, "translationVcyl", component, Vec3::Zero()));
}

void ReadWrapObjects(ReadContext& ctx, const pugi::xml_node& owner, int body,
                     const std::string& owner_path) {
  const XmlDocument& doc = ctx.doc();
  for (pugi::xml_node wrap : ObjectsOf(owner.child("WrapObjectSet"))) {
    model::WrapObjectSpec spec;
    spec.name = NameOf(wrap);
    spec.type = wrap.name();
    const std::string component = owner_path + "/wrapobjectset/" + spec.name;
    spec.body = body;
    spec.X_BW = MakeTransform(ReadVec3Or(doc, wrap, "xyz_body_rotation", component, Vec3::Zero()),
                              ReadVec3Or(doc, wrap, "translation", component, Vec3::Zero()));
    spec.quadrant = TextOf(wrap, "quadrant");
    if (spec.quadrant.empty()) spec.quadrant = "all";
    spec.active = ReadBoolOr(doc, wrap, "active", component, true);
    spec.dimensions = ReadNumericLeaves(
        doc, wrap, component,
        {"xyz_body_rotation", "translation", "active", "xyz_body_rotationVcyl", "translationVcyl"});
    ReadWrapDirection(doc, wrap, component, "wrapDirection", "wrap_direction", spec.dimensions);
    if (spec.type == "WrapDoubleCylinderObst") ReadVCylinder(ctx, wrap, component, spec);
    spec.where = doc.Where(wrap);
    ctx.IndexWrapObject(spec.name);
    ctx.spec().bodies[body].wrap_objects.push_back(std::move(spec));
  }
}

// The component path of a 4.x element from its ancestors' names ("/jointset/knee/femur_offset").
std::string GenericPath(const pugi::xml_node& node) {
  std::vector<std::string> segments;
  for (pugi::xml_node n = node; n && n.type() == pugi::node_element; n = n.parent()) {
    const std::string_view tag = n.name();
    if (tag == "Model") break;
    if (tag.size() > 3 && tag.substr(tag.size() - 3) == "Set") {
      segments.push_back(Lower(tag));
    } else if (tag == "Ground") {
      segments.push_back("ground");
    } else if (n.attribute("name")) {
      segments.push_back(NameOf(n));
    }
  }
  std::string path;
  for (auto it = segments.rbegin(); it != segments.rend(); ++it) path += "/" + *it;
  return path;
}

// The parent socket of an offset frame: 4.x `socket_parent`, or the 4.0 beta
// `<connectors><Connector_PhysicalFrame_ name="parent"><connectee_name>`.
pugi::xml_node ParentSocket(const pugi::xml_node& frame) {
  if (pugi::xml_node socket = frame.child("socket_parent")) return socket;
  for (pugi::xml_node connector : frame.child("connectors").children()) {
    if (NameOf(connector) == "parent") return connector.child("connectee_name");
  }
  return {};
}

void CollectOffsetFrames(ReadContext& ctx, const pugi::xml_node& root,
                         std::vector<std::pair<pugi::xml_node, std::string>>& found) {
  const XmlDocument& doc = ctx.doc();
  for (pugi::xml_node node : root.children()) {
    if (node.type() != pugi::node_element) continue;
    const std::string_view tag = node.name();
    if (tag == "Station") ctx.AddStation(GenericPath(node), node);
    if (tag == "StationDefinedFrame") {
      const std::string path = GenericPath(node);
      FrameEntry entry;
      entry.node = node;
      entry.component = path;
      entry.station_frame = node;
      if (!ctx.AddOffsetFrame(path, std::move(entry))) {
        doc.Fail(node, path, "duplicate frame path '" + path + "'");
      }
      found.emplace_back(node, path);
    }
    if (tag == "PhysicalOffsetFrame") {
      const std::string path = GenericPath(node);
      FrameEntry entry;
      entry.node = node;
      entry.component = path;
      entry.parent_node = ParentSocket(node);
      if (!entry.parent_node) doc.Fail(node, path, "PhysicalOffsetFrame has no <socket_parent>");
      entry.parent_path = std::string(XmlDocument::Text(entry.parent_node));
      entry.X_PF = MakeTransform(ReadVec3Or(doc, node, "orientation", path, Vec3::Zero()),
                                 ReadVec3Or(doc, node, "translation", path, Vec3::Zero()));
      if (!ctx.AddOffsetFrame(path, std::move(entry))) {
        doc.Fail(node, path, "duplicate frame path '" + path + "'");
      }
      found.emplace_back(node, path);
    }
    CollectOffsetFrames(ctx, node, found);
  }
}

}  // namespace

void ReadBodies(ReadContext& ctx, const pugi::xml_node& model) {
  const XmlDocument& doc = ctx.doc();
  model::ModelSpec& spec = ctx.spec();
  model::BodySpec ground;
  ground.name = "ground";
  ground.path = "/ground";
  pugi::xml_node ground_node = model.child("Ground");
  ground.where = doc.Where(ground_node ? ground_node : model);
  spec.bodies.push_back(std::move(ground));
  ctx.IndexBody("ground", model::kGroundIndex);
  ctx.AddBodyFrame("/ground", model::kGroundIndex, ground_node ? ground_node : model);

  // Bodies first (so every frame can be resolved), their geometry after the offset frames.
  std::vector<std::pair<pugi::xml_node, int>> body_nodes;
  if (ground_node) body_nodes.emplace_back(ground_node, model::kGroundIndex);
  for (pugi::xml_node node : ObjectsOf(model.child("BodySet"))) {
    const std::string name = NameOf(node);
    std::string component = "/bodyset/" + name;
    if (std::string_view(node.name()) != "Body") {
      ctx.Warn(node, component, "<" + std::string(node.name()) + "> in BodySet read as a Body");
    }
    if (name.empty()) doc.Fail(node, "/bodyset", "a body has no name");
    int index;
    if (name == "ground" && !ground_node) {
      // 3.x: ground is a body named "ground".
      index = model::kGroundIndex;
      spec.bodies[0].where = doc.Where(node);
      if (ReadDoubleOr(doc, node, "mass", "/ground", 0.0) != 0.0) {
        ctx.Warn(node, "/ground", "ground's mass is ignored");
      }
    } else {
      if (int other = ctx.BodyIndex(name); other != model::kNone) {
        doc.Fail(node, component,
                 "duplicate body name '" + name + "' (also at line " +
                     std::to_string(spec.bodies[other].where.line) + ")");
      }
      model::BodySpec body;
      body.name = name;
      body.path = component;
      pugi::xml_node mass = node.child("mass");
      if (!mass) ctx.Warn(node, component, "body has no <mass>; using 0");
      body.mass = mass ? doc.ReadDouble(mass, component) : 0.0;
      if (body.mass < 0) doc.Fail(mass, component, "negative mass");
      body.mass_center = ReadVec3Or(doc, node, "mass_center", component, Vec3::Zero());
      body.inertia = ReadInertia(ctx, node, component);
      body.where = doc.Where(node);
      index = static_cast<int>(spec.bodies.size());
      spec.bodies.push_back(std::move(body));
      ctx.IndexBody(name, index);
      ctx.AddBodyFrame(component, index, node);
    }
    for (pugi::xml_node child : node.children()) {
      if (child.type() == pugi::node_element && !IsKnownBodyProperty(child.name())) {
        ctx.Warn(child, component,
                 "unknown body property <" + std::string(child.name()) + "> ignored",
                 std::string("body:") + child.name());
      }
    }
    body_nodes.emplace_back(node, index);
  }

  std::vector<std::pair<pugi::xml_node, std::string>> offset_frames;
  CollectOffsetFrames(ctx, model, offset_frames);

  for (const auto& [node, index] : body_nodes) {
    const std::string& path = spec.bodies[index].path;
    ReadAttachedGeometry(ctx, node, path, path);
    if (pugi::xml_node visible = node.child("VisibleObject")) {
      ReadVisibleObject(ctx, visible, index, path, path);
    }
    ReadWrapObjects(ctx, node, index, path);
  }
  for (const auto& [node, path] : offset_frames) {
    ReadAttachedGeometry(ctx, node, path, path);
    if (node.child("WrapObjectSet")) {
      const FrameEntry* frame = nullptr;
      ctx.ResolveFrame("", path, node, path, &frame);
      const size_t first = spec.bodies[frame->body].wrap_objects.size();
      ReadWrapObjects(ctx, node, frame->body, path);
      auto& wraps = spec.bodies[frame->body].wrap_objects;
      for (size_t i = first; i < wraps.size(); ++i) wraps[i].X_BW = frame->X_BF * wraps[i].X_BW;
    }
  }
}

}  // namespace sinew::io::internal

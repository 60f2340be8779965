// Joints and coordinates in the three layouts found in real files:
// - 4.x: <JointSet> of joints with socket_parent_frame / socket_child_frame paths (absolute or
//   relative to the joint) to bodies, ground or PhysicalOffsetFrames;
// - 3.05 (30501 .. 30504): <JointSet> of joints with <connectors> naming the parent and child
//   bodies, plus location/orientation_in_parent and location/orientation_in_child;
// - up to 3.x: each <Body> nests its <Joint> with parent_body, location_in_parent,
//   orientation_in_parent (on the parent) and location, orientation (on the body itself).
// In the last two the offsets become frames named as OpenSim 4's upgrade names them:
// /jointset/<joint>/<parent body>_offset and /jointset/<joint>/<child body>_offset.
//
// 3.x `reverse`: OpenSim 4 removed the property in format 30514. Its upgrade step
// (Joint::updateFromXMLNode, opensim-core pull request #1577 "Remove user-facing reverse property
// from Joint") swaps the parent and child frame connections of a joint whose `reverse` was true,
// after the 30505 step made the two offset frames. We do the same: the parent becomes the body
// that owns the joint, with its (location, orientation) frame, and the child the body named by
// `parent_body`, with the *_in_parent frame. JointSpec::reverse keeps the flag.
#include <sinew/functions/constant.h>
#include <sinew/functions/linear_function.h>
#include <sinew/io/internal/osim_context.h>
#include <sinew/io/internal/read_function.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <string_view>
#include <unordered_map>

namespace sinew::io::internal {
namespace {

struct KindInfo {
  std::string_view tag;
  model::JointType kind;
  int num_coordinates;  // -1: any (CustomJoint), as many as its axes use
};

constexpr KindInfo kKinds[] = {
    {"PinJoint", model::JointType::kPin, 1},
    {"SliderJoint", model::JointType::kSlider, 1},
    {"UniversalJoint", model::JointType::kUniversal, 2},
    {"GimbalJoint", model::JointType::kGimbal, 3},
    {"BallJoint", model::JointType::kBall, 3},
    {"FreeJoint", model::JointType::kFree, 6},
    {"PlanarJoint", model::JointType::kPlanar, 3},
    {"EllipsoidJoint", model::JointType::kEllipsoid, 3},
    {"WeldJoint", model::JointType::kWeld, 0},
    {"ScapulothoracicJoint", model::JointType::kScapulothoracic, 4},
    {"CustomJoint", model::JointType::kCustom, -1},
    {"ConstantCurvatureJoint", model::JointType::kConstantCurvature, 3},
};

const KindInfo* FindKind(std::string_view tag) {
  for (const KindInfo& info : kKinds) {
    if (info.tag == tag) return &info;
  }
  return nullptr;
}

// The motion of a joint's i-th coordinate for the joints with a fixed coordinate layout.
model::MotionType FixedMotion(model::JointType kind, int i) {
  switch (kind) {
    case model::JointType::kSlider:
      return model::MotionType::kTranslational;
    case model::JointType::kFree:
      return i < 3 ? model::MotionType::kRotational : model::MotionType::kTranslational;
    case model::JointType::kPlanar:
      return i == 0 ? model::MotionType::kRotational : model::MotionType::kTranslational;
    default:
      return model::MotionType::kRotational;
  }
}

constexpr std::string_view kAxisNames[6] = {"rotation1",    "rotation2",    "rotation3",
                                            "translation1", "translation2", "translation3"};

bool IsKnownCoordinateProperty(std::string_view tag) {
  static constexpr std::string_view kKnown[] = {"default_value",
                                                "default_speed_value",
                                                "initial_value",
                                                "range",
                                                "clamped",
                                                "locked",
                                                "prescribed_function",
                                                "prescribed",
                                                "motion_type",
                                                "is_free_to_satisfy_constraints",
                                                "restraint_function",
                                                "min_restraint_function",
                                                "max_restraint_function",
                                                "restraint_active",
                                                "dynamic_restraint_function",
                                                "speed_name",
                                                "tolerance",
                                                "stiffness",
                                                "keys"};
  for (std::string_view known : kKnown) {
    if (tag == known) return true;
  }
  return false;
}

// Joint properties the reader uses; other non-numeric ones get one warning per tag.
bool IsKnownJointProperty(std::string_view tag) {
  static constexpr std::string_view kKnown[] = {"socket_parent_frame",
                                                "socket_child_frame",
                                                "coordinates",
                                                "CoordinateSet",
                                                "frames",
                                                "SpatialTransform",
                                                "parent_body",
                                                "reverse",
                                                "connectors",
                                                "FrameGeometry",
                                                "components",
                                                "Appearance",
                                                "location_in_parent",
                                                "orientation_in_parent",
                                                "location",
                                                "orientation",
                                                "location_in_child",
                                                "orientation_in_child"};
  for (std::string_view known : kKnown) {
    if (tag == known) return true;
  }
  return false;
}

class JointReader {
 public:
  explicit JointReader(ReadContext& ctx) : ctx_(ctx), doc_(ctx.doc()), spec_(ctx.spec()) {}

  // A joint of a <JointSet> (4.x sockets or 3.05 connectors).
  void ReadJointSetJoint(const pugi::xml_node& node) {
    model::JointSpec& joint = StartJoint(node);
    const int index = static_cast<int>(spec_.joints.size()) - 1;
    pugi::xml_node parent_socket = node.child("socket_parent_frame");
    pugi::xml_node child_socket = node.child("socket_child_frame");
    if (parent_socket || child_socket) {
      if (!parent_socket) doc_.Fail(node, joint.path, "joint has no <socket_parent_frame>");
      if (!child_socket) doc_.Fail(node, joint.path, "joint has no <socket_child_frame>");
      const FrameEntry* parent = nullptr;
      const FrameEntry* child = nullptr;
      joint.parent_frame = ctx_.ResolveFrame(joint.path, XmlDocument::Text(parent_socket),
                                             parent_socket, joint.path, &parent);
      joint.child_frame = ctx_.ResolveFrame(joint.path, XmlDocument::Text(child_socket),
                                            child_socket, joint.path, &child);
      joint.parent_body = parent->body;
      joint.X_PF = parent->X_BF;
      joint.child_body = child->body;
      joint.X_BM = child->X_BF;
    } else if (pugi::xml_node connectors = node.child("connectors")) {
      pugi::xml_node parent_name, child_name;
      for (pugi::xml_node connector : connectors.children()) {
        const std::string which = NameOf(connector);
        if (which == "parent_body" || which == "parent_frame") {
          parent_name = connector.child("connectee_name");
        } else if (which == "child_body" || which == "child_frame") {
          child_name = connector.child("connectee_name");
        }
      }
      if (!parent_name) doc_.Fail(connectors, joint.path, "no parent_body connector");
      if (!child_name) doc_.Fail(connectors, joint.path, "no child_body connector");
      const int parent = BodyByName(parent_name, joint.path, "parent body");
      const int child = BodyByName(child_name, joint.path, "child body");
      ConnectWithOffsets(node, index, parent, "location_in_parent", "orientation_in_parent", child,
                         "location_in_child", "orientation_in_child");
    } else {
      doc_.Fail(node, joint.path, "joint names neither parent nor child frame");
    }
    FinishJoint(node, index);
  }

  // A joint nested in the <Joint> of a 3.x <Body> (the child body).
  void ReadNestedJoint(const pugi::xml_node& node, int child_body) {
    std::string fallback_name;
    if (NameOf(node).empty()) {
      // Unnamed joints load in OpenSim 3; 4.x needs a name. Ours: <parent>_to_<child>.
      fallback_name = TextOf(node, "parent_body") + "_to_" + spec_.bodies[child_body].name;
      ctx_.Warn(node, spec_.bodies[child_body].path,
                "the joint has no name; named '" + fallback_name + "'");
    }
    model::JointSpec& joint = StartJoint(node, fallback_name);
    const int index = static_cast<int>(spec_.joints.size()) - 1;
    pugi::xml_node parent_node = node.child("parent_body");
    if (!parent_node) doc_.Fail(node, joint.path, "joint has no <parent_body>");
    const int parent = BodyByName(parent_node, joint.path, "parent_body");
    ConnectWithOffsets(node, index, parent, "location_in_parent", "orientation_in_parent",
                       child_body, "location", "orientation");
    FinishJoint(node, index);
  }

 private:
  // Fills the fields every layout shares and adds the joint to the spec.
  model::JointSpec& StartJoint(const pugi::xml_node& node, const std::string& fallback_name = "") {
    model::JointSpec joint;
    joint.name = NameOf(node);
    if (joint.name.empty()) joint.name = fallback_name;
    joint.type = node.name();
    joint.path = "/jointset/" + joint.name;
    if (joint.name.empty()) doc_.Fail(node, "/jointset", "a joint has no name");
    if (int other = ctx_.JointIndex(joint.name); other != model::kNone) {
      // Paths must stay unique (frames and coordinates hang under them): number the repeat.
      int& n = next_suffix_.try_emplace(joint.name, 2).first->second;
      while (ctx_.HasFrame(joint.path + "_" + std::to_string(n)) ||
             ctx_.JointPathTaken(joint.path + "_" + std::to_string(n))) {
        ++n;
      }
      const std::string unique = joint.path + "_" + std::to_string(n++);
      ctx_.Warn(node, joint.path,
                "duplicate joint name '" + joint.name + "' (also at line " +
                    std::to_string(spec_.joints[other].where.line) + "); its path here is '" +
                    unique + "'");
      joint.path = unique;
    }
    const KindInfo* info = FindKind(joint.type);
    joint.kind = info ? info->kind : model::JointType::kUnknown;
    if (!info) {
      ctx_.Warn(node, joint.path, "unknown joint type <" + joint.type + ">: read with its frames",
                "jointtype:" + joint.type);
    }
    for (pugi::xml_node child : node.children()) {
      if (child.type() != pugi::node_element || IsKnownJointProperty(child.name())) continue;
      if (IsNumberList(XmlDocument::Text(child))) continue;  // a parameter, read below
      ctx_.Warn(child, joint.path,
                "joint property <" + std::string(child.name()) + "> kept in the element, not used",
                std::string("joint:") + joint.type + ":" + child.name());
    }
    joint.element = ToElement(doc_, node);
    joint.where = doc_.Where(node);
    // Properties that are not "parameters" (radii_x_y_z, ...): the 3.x offsets.
    joint.parameters =
        ReadNumericLeaves(doc_, node, joint.path,
                          {"location_in_parent", "orientation_in_parent", "location", "orientation",
                           "location_in_child", "orientation_in_child", "reverse"});
    ctx_.IndexJoint(joint.name, joint.path, static_cast<int>(spec_.joints.size()));
    spec_.joints.push_back(std::move(joint));
    return spec_.joints.back();
  }

  // A body named in a 3.x property (a name, or 3.05's "../name").
  int BodyByName(const pugi::xml_node& node, const std::string& component, const char* what) {
    std::string_view text = XmlDocument::Text(node);
    const size_t slash = text.rfind('/');
    if (slash != std::string_view::npos) text = text.substr(slash + 1);
    if (text.empty()) doc_.Fail(node, component, std::string(what) + " is empty");
    const int body = ctx_.BodyIndex(std::string(text));
    if (body == model::kNone) {
      doc_.Fail(node, component, std::string(what) + " '" + std::string(text) + "' does not exist");
    }
    return body;
  }

  // 3.x and 3.05: the offsets become frames <parent>_offset and <child>_offset under the joint.
  void ConnectWithOffsets(const pugi::xml_node& node, int index, int parent, const char* p_loc,
                          const char* p_ori, int child, const char* c_loc, const char* c_ori) {
    model::JointSpec& joint = spec_.joints[index];
    if (parent == child) {
      doc_.Fail(node, joint.path,
                "joint connects body '" + spec_.bodies[parent].name + "' to itself");
    }
    joint.parent_body = parent;
    joint.child_body = child;
    joint.reverse = ReadBoolOr(doc_, node, "reverse", joint.path, false);
    const Transform X_PF = MakeTransform(ReadVec3Or(doc_, node, p_ori, joint.path, Vec3::Zero()),
                                         ReadVec3Or(doc_, node, p_loc, joint.path, Vec3::Zero()));
    const Transform X_BM = MakeTransform(ReadVec3Or(doc_, node, c_ori, joint.path, Vec3::Zero()),
                                         ReadVec3Or(doc_, node, c_loc, joint.path, Vec3::Zero()));
    joint.parent_frame = AddUpgradeFrame(node, joint.path, parent, X_PF);
    joint.child_frame = AddUpgradeFrame(node, joint.path, child, X_BM);
    joint.X_PF = X_PF;
    joint.X_BM = X_BM;
    if (joint.reverse) {
      // OpenSim's 30514 upgrade swaps the parent and child frames of a reversed joint.
      std::swap(joint.parent_body, joint.child_body);
      std::swap(joint.parent_frame, joint.child_frame);
      std::swap(joint.X_PF, joint.X_BM);
    }
  }

  std::string AddUpgradeFrame(const pugi::xml_node& node, const std::string& joint_path, int body,
                              const Transform& X_BF) {
    const std::string path = joint_path + "/" + spec_.bodies[body].name + "_offset";
    FrameEntry entry;
    entry.node = node;
    entry.component = path;
    entry.parent_path = spec_.bodies[body].path;
    entry.parent_node = node;
    entry.X_PF = X_BF;
    if (!ctx_.AddOffsetFrame(path, std::move(entry))) {
      doc_.Fail(node, joint_path, "duplicate frame path '" + path + "'");
    }
    const FrameEntry* resolved = nullptr;
    ctx_.ResolveFrame("", path, node, path, &resolved);
    return path;
  }

  // Coordinates and, for a CustomJoint, the spatial transform.
  void FinishJoint(const pugi::xml_node& node, int index) {
    const std::string path = spec_.joints[index].path;
    const model::JointType kind = spec_.joints[index].kind;
    pugi::xml_node list = node.child("coordinates");
    if (!list) list = node.child("CoordinateSet");
    std::vector<int> coords;
    for (pugi::xml_node c : ObjectsOf(list)) coords.push_back(ReadCoordinate(c, index, path));

    const KindInfo* info = FindKind(spec_.joints[index].type);
    if (coords.empty() && info && info->num_coordinates > 0) {
      // OpenSim builds a joint's coordinates when the file lists none: <joint>_coord_<i>.
      ctx_.Warn(node, path,
                "no coordinates listed: made " + std::to_string(info->num_coordinates) +
                    " with default properties, named " + spec_.joints[index].name + "_coord_<i>");
      for (int i = 0; i < info->num_coordinates; ++i) {
        model::CoordinateSpec c;
        c.name = spec_.joints[index].name + "_coord_" + std::to_string(i);
        c.path = path + "/" + c.name;
        c.joint = index;
        c.where = doc_.Where(node);
        ctx_.IndexCoordinate(c.name, c.path, static_cast<int>(spec_.coordinates.size()));
        coords.push_back(static_cast<int>(spec_.coordinates.size()));
        spec_.coordinates.push_back(std::move(c));
        explicit_motion_.push_back(false);
      }
    }
    if (kind == model::JointType::kCustom) {
      ReadSpatialTransform(node, index, coords);
    } else {
      spec_.joints[index].coordinates = coords;
      if (info && static_cast<int>(coords.size()) != info->num_coordinates) {
        doc_.Fail(node, path,
                  std::string(info->tag) + " needs " + std::to_string(info->num_coordinates) +
                      " coordinate" + (info->num_coordinates == 1 ? "" : "s") + ", found " +
                      std::to_string(coords.size()));
      }
      for (size_t i = 0; i < coords.size(); ++i) {
        model::CoordinateSpec& c = spec_.coordinates[coords[i]];
        if (!explicit_motion_[coords[i]]) c.motion_type = FixedMotion(kind, static_cast<int>(i));
      }
    }
  }

  int ReadCoordinate(const pugi::xml_node& node, int joint, const std::string& joint_path) {
    model::CoordinateSpec c;
    c.name = NameOf(node);
    c.path = joint_path + "/" + c.name;
    const std::string& component = c.path;
    if (c.name.empty()) doc_.Fail(node, joint_path, "a coordinate has no name");
    // Duplicate names are summarized once in ValidateSpec; a reference by such a name fails.
    c.joint = joint;
    c.default_value = ReadDoubleOr(doc_, node, "default_value", component, 0.0);
    c.default_speed_value = ReadDoubleOr(doc_, node, "default_speed_value", component, 0.0);
    if (pugi::xml_node range = node.child("range")) {
      std::vector<double> r = doc_.ReadNumbers(range, component, 2, NumberRange::kAllowInfinite);
      c.range_min = r[0];
      c.range_max = r[1];
      if (r[0] > r[1]) doc_.Fail(range, component, "<range> minimum exceeds maximum");
      if (c.default_value < r[0] || c.default_value > r[1]) {
        std::ostringstream text;
        text << "<default_value> " << c.default_value << " is outside <range> [" << r[0] << ", "
             << r[1] << "]; the coordinate starts there, beyond its range";
        ctx_.Warn(range, component, text.str());
      }
    }
    c.clamped = ReadBoolOr(doc_, node, "clamped", component, false);
    c.free_to_satisfy_constraints =
        ReadBoolOr(doc_, node, "is_free_to_satisfy_constraints", component, false);
    c.locked = ReadBoolOr(doc_, node, "locked", component, false);
    if (pugi::xml_node function = node.child("prescribed_function")) {
      c.prescribed_function = ReadFunctionProperty(doc_, function, component);
    }
    // Absent <prescribed> takes the property's default, false (no corpus file has a
    // prescribed_function without it, so older versions give no other evidence).
    c.prescribed = ReadBoolOr(doc_, node, "prescribed", component, false);
    if (c.prescribed && !c.prescribed_function) {
      ctx_.Warn(node, component, "prescribed without a prescribed_function: not prescribed");
      c.prescribed = false;
    }
    bool explicit_motion = false;
    if (pugi::xml_node motion = node.child("motion_type")) {
      const std::string text = Lower(XmlDocument::Text(motion));
      explicit_motion = true;
      if (text == "rotational") {
        c.motion_type = model::MotionType::kRotational;
      } else if (text == "translational") {
        c.motion_type = model::MotionType::kTranslational;
      } else if (text == "coupled") {
        c.motion_type = model::MotionType::kCoupled;
      } else {
        doc_.Fail(motion, component,
                  "<motion_type> must be rotational, translational or coupled, found '" +
                      std::string(text) + "'");
      }
    }
    for (pugi::xml_node child : node.children()) {
      if (child.type() == pugi::node_element && !IsKnownCoordinateProperty(child.name())) {
        ctx_.Warn(child, component,
                  "unknown coordinate property <" + std::string(child.name()) + "> ignored",
                  std::string("coordinate:") + child.name());
      }
    }
    c.where = doc_.Where(node);
    ctx_.IndexCoordinate(c.name, c.path, static_cast<int>(spec_.coordinates.size()));
    spec_.coordinates.push_back(std::move(c));
    explicit_motion_.push_back(explicit_motion);
    return static_cast<int>(spec_.coordinates.size()) - 1;
  }

  // The function of a TransformAxis: 3.x wraps it in <function>, 4.x writes the Function element
  // itself with name="function".
  functions::FunctionPtr ReadAxisFunction(const pugi::xml_node& axis,
                                          const std::string& component) {
    if (pugi::xml_node wrapper = axis.child("function")) {
      return ReadFunctionProperty(doc_, wrapper, component);
    }
    for (pugi::xml_node child : axis.children()) {
      if (child.type() == pugi::node_element && IsFunctionType(child.name())) {
        return ReadFunction(doc_, child, component);
      }
    }
    for (pugi::xml_node child : axis.children()) {
      if (child.type() == pugi::node_element && NameOf(child) == "function") {
        return ReadFunction(doc_, child, component);  // fails: unknown function type
      }
    }
    return nullptr;
  }

  void ReadSpatialTransform(const pugi::xml_node& node, int index, const std::vector<int>& own) {
    model::JointSpec& joint = spec_.joints[index];
    const std::string path = joint.path;
    pugi::xml_node transform = node.child("SpatialTransform");
    std::array<pugi::xml_node, 6> axes;
    if (transform) {
      for (pugi::xml_node axis : ObjectsOf(transform)) {
        const std::string name = NameOf(axis);
        int slot = -1;
        for (int i = 0; i < 6; ++i) {
          if (kAxisNames[i] == name) slot = i;
        }
        if (slot < 0) {
          doc_.Fail(axis, path,
                    "TransformAxis '" + name + "' is not one of rotation1..3, translation1..3");
        }
        if (axes[slot]) doc_.Fail(axis, path, "TransformAxis '" + name + "' appears twice");
        axes[slot] = axis;
      }
    } else {
      ctx_.Warn(node, path, "CustomJoint has no SpatialTransform: it allows no motion");
    }
    std::vector<int> order;
    std::vector<model::TransformAxisSpec> spatial(6);
    for (int i = 0; i < 6; ++i) {
      model::TransformAxisSpec& axis = spatial[i];
      axis.name = std::string(kAxisNames[i]);
      axis.axis = Vec3::Unit(i % 3);
      const std::string component = path + "/" + axis.name;
      if (pugi::xml_node a = axes[i]) {
        axis.axis = ReadVec3Or(doc_, a, "axis", component, axis.axis);
        if (axis.axis.norm() == 0) doc_.Fail(a.child("axis"), component, "<axis> is zero");
        std::istringstream names(TextOf(a, "coordinates"));
        std::string name;
        while (names >> name) {
          int found = model::kNone;
          for (int c : own) {
            if (spec_.coordinates[c].name == name) found = c;
          }
          if (found == model::kNone) {
            doc_.Fail(a.child("coordinates"), component,
                      "coordinate '" + name + "' is not one of the joint's coordinates");
          }
          axis.coordinates.push_back(found);
          if (std::find(order.begin(), order.end(), found) == order.end()) order.push_back(found);
        }
        axis.function = ReadAxisFunction(a, component);
        if (axis.function && axis.function->NumArguments() != 1 &&
            axis.function->NumArguments() != static_cast<int>(axis.coordinates.size())) {
          doc_.Fail(a, component,
                    "the function takes " + std::to_string(axis.function->NumArguments()) +
                        " arguments for " + std::to_string(axis.coordinates.size()) +
                        " coordinates");
        }
      }
      if (!axis.function) {
        if (axis.coordinates.size() > 1) {
          doc_.Fail(axes[i], component, "an axis with several coordinates needs a function");
        }
        // OpenSim's defaults: the identity of one coordinate, or a constant 0.
        if (axis.coordinates.size() == 1) {
          axis.function = std::make_shared<functions::LinearFunction>(1.0, 0.0);
        } else {
          axis.function = std::make_shared<functions::Constant>(0.0);
        }
      }
    }
    for (int c : own) {
      if (std::find(order.begin(), order.end(), c) == order.end()) {
        ctx_.Warn(node, spec_.coordinates[c].path, "coordinate is not used by any TransformAxis");
        order.push_back(c);
      }
    }
    // Motion type: rotational if it drives a rotation axis through a LinearFunction of slope
    // +-1, else translational if it drives a translation axis so, else coupled.
    for (int c : order) {
      if (explicit_motion_[c]) continue;
      bool rotational = false, translational = false;
      for (int i = 0; i < 6; ++i) {
        const model::TransformAxisSpec& axis = spatial[i];
        if (axis.coordinates.size() != 1 || axis.coordinates[0] != c) continue;
        if (axis.function->TypeName() != "LinearFunction") continue;
        if (std::abs(std::abs(axis.function->CalcDerivative(0.0, 1)) - 1.0) > 0.0) continue;
        (i < 3 ? rotational : translational) = true;
      }
      spec_.coordinates[c].motion_type = rotational      ? model::MotionType::kRotational
                                         : translational ? model::MotionType::kTranslational
                                                         : model::MotionType::kCoupled;
    }
    joint.coordinates = std::move(order);
    joint.spatial_transform = std::move(spatial);
  }

  ReadContext& ctx_;
  const XmlDocument& doc_;
  model::ModelSpec& spec_;
  std::vector<bool> explicit_motion_;  // per coordinate: motion_type given in the file
  std::unordered_map<std::string, int> next_suffix_;  // duplicate joint name -> next number
};

}  // namespace

void ReadJoints(ReadContext& ctx, const pugi::xml_node& model) {
  JointReader reader(ctx);
  for (pugi::xml_node node : ObjectsOf(model.child("JointSet"))) reader.ReadJointSetJoint(node);
  for (pugi::xml_node body : ObjectsOf(model.child("BodySet"))) {
    const std::string name = NameOf(body);
    pugi::xml_node wrapper = body.child("Joint");
    if (!wrapper) continue;
    for (pugi::xml_node node : wrapper.children()) {
      if (node.type() != pugi::node_element) continue;
      if (name == "ground") {
        ctx.doc().Fail(node, "/ground", "ground cannot be the child of a joint");
      }
      reader.ReadNestedJoint(node, ctx.BodyIndex(name));
    }
  }
}

}  // namespace sinew::io::internal

// Forces, actuators and muscles with their geometry paths (path points, conditional and moving
// path points, path wraps). Muscle parameters stay in ForceSpec::element.
#include <sinew/functions/constant.h>
#include <sinew/io/internal/osim_context.h>
#include <sinew/io/internal/read_function.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string_view>

namespace sinew::io::internal {

int ResolveCoordinateName(ReadContext& ctx, const pugi::xml_node& node, std::string_view text,
                          const std::string& component) {
  const auto& coords = ctx.spec().coordinates;
  if (int by_path = ctx.CoordinateByPath(std::string(text)); by_path != model::kNone)
    return by_path;
  const size_t slash = text.rfind('/');
  const std::string_view name = slash == std::string_view::npos ? text : text.substr(slash + 1);
  const std::vector<int>& named = ctx.CoordinatesNamed(std::string(name));
  const int count = static_cast<int>(named.size());
  const int found = named.empty() ? model::kNone : named.front();
  const std::string tag = node.name();
  if (count == 0) {
    ctx.doc().Fail(node, component, "<" + tag + "> '" + std::string(text) + "' does not exist");
  }
  if (count > 1) {
    // OpenSim 3 looks names up in its CoordinateSet, which returns the first match.
    ctx.Warn(node, component,
             "<" + tag + "> '" + std::string(text) + "' is ambiguous: " + std::to_string(count) +
                 " coordinates have that name; using the first, '" + coords[found].path + "'");
  }
  return found;
}

namespace {

// A coordinate named by a 4.x socket path or a 3.x name; fails when missing or ambiguous.
int ResolveCoordinate(ReadContext& ctx, const pugi::xml_node& node, const std::string& component) {
  return ResolveCoordinateName(ctx, node, XmlDocument::Text(node), component);
}

// The frame a path point, marker or contact geometry is fixed to: 4.x `socket_tag` (relative to
// `own_path`) or the 3.x body name in `body_tag`.
const FrameEntry* ResolveAttachment(ReadContext& ctx, const pugi::xml_node& node,
                                    const std::string& own_path, const char* socket_tag,
                                    const char* body_tag, std::string* frame_path) {
  if (pugi::xml_node socket = node.child(socket_tag)) {
    const FrameEntry* frame = nullptr;
    *frame_path = ctx.ResolveFrame(own_path, XmlDocument::Text(socket), socket, own_path, &frame);
    return frame;
  }
  if (pugi::xml_node body = node.child(body_tag)) {
    std::string_view name = XmlDocument::Text(body);
    const std::string path = name == "ground" ? "/ground" : "/bodyset/" + std::string(name);
    if (name.empty() || !ctx.HasFrame(path)) {
      ctx.doc().Fail(body, own_path,
                     "<" + std::string(body_tag) + "> '" + std::string(name) + "' does not exist");
    }
    const FrameEntry* frame = nullptr;
    *frame_path = ctx.ResolveFrame("", path, body, own_path, &frame);
    return frame;
  }
  ctx.doc().Fail(node, own_path,
                 "names no frame (<" + std::string(socket_tag) + "> or <" + body_tag + ">)");
}

model::PathPointSpec ReadPathPoint(ReadContext& ctx, const pugi::xml_node& node,
                                   const std::string& path_path) {
  const XmlDocument& doc = ctx.doc();
  model::PathPointSpec point;
  point.name = NameOf(node);
  point.type = node.name();
  // 1.9 names: MusclePoint, MuscleViaPoint, MovingMusclePoint.
  if (point.type == "MusclePoint") point.type = "PathPoint";
  if (point.type == "MuscleViaPoint") point.type = "ConditionalPathPoint";
  if (point.type == "MovingMusclePoint") point.type = "MovingPathPoint";
  const std::string component = path_path + "/" + point.name;
  const FrameEntry* frame =
      ResolveAttachment(ctx, node, component, "socket_parent_frame", "body", &point.frame);
  point.body = frame->body;
  point.X_BF = frame->X_BF;
  const Vec3 location = ReadVec3Or(doc, node, "location", component, Vec3::Zero());
  point.location = frame->X_BF * location;
  if (point.type == "ConditionalPathPoint") {
    pugi::xml_node coordinate = node.child("socket_coordinate");
    if (!coordinate) coordinate = node.child("coordinate");
    if (!coordinate) doc.Fail(node, component, "ConditionalPathPoint names no coordinate");
    point.coordinate = ResolveCoordinate(ctx, coordinate, component);
    pugi::xml_node range = node.child("range");
    if (!range) doc.Fail(node, component, "ConditionalPathPoint has no <range>");
    std::vector<double> r = doc.ReadNumbers(range, component, 2, NumberRange::kAllowInfinite);
    point.range_min = r[0];
    point.range_max = r[1];
  } else if (point.type == "MovingPathPoint") {
    static constexpr const char* kFunctions[3] = {"x_location", "y_location", "z_location"};
    static constexpr const char* kSockets[3] = {"socket_x_coordinate", "socket_y_coordinate",
                                                "socket_z_coordinate"};
    static constexpr const char* kNames[3] = {"x_coordinate", "y_coordinate", "z_coordinate"};
    for (int i = 0; i < 3; ++i) {
      pugi::xml_node function = node.child(kFunctions[i]);
      if (function) point.location_functions[i] = ReadFunctionProperty(doc, function, component);
      pugi::xml_node coordinate = node.child(kSockets[i]);
      if (!coordinate) coordinate = node.child(kNames[i]);
      if (coordinate && !XmlDocument::Text(coordinate).empty()) {
        point.location_coordinates[i] = ResolveCoordinate(ctx, coordinate, component);
      }
      if (!point.location_functions[i]) {
        // No function: the coordinate of `location` stays fixed.
        point.location_functions[i] = std::make_shared<functions::Constant>(location[i]);
      }
    }
  } else if (point.type != "PathPoint") {
    ctx.Warn(node, component, "unknown path point type <" + point.type + "> read as a PathPoint",
             "pathpoint:" + point.type);
  }
  return point;
}

model::GeometryPathSpec ReadGeometryPath(ReadContext& ctx, const pugi::xml_node& points_owner,
                                         const std::string& path_path) {
  const XmlDocument& doc = ctx.doc();
  model::GeometryPathSpec path;
  pugi::xml_node point_set = points_owner.child("PathPointSet");
  if (!point_set) point_set = points_owner.child("MusclePointSet");
  for (pugi::xml_node node : ObjectsOf(point_set)) {
    path.points.push_back(ReadPathPoint(ctx, node, path_path));
  }
  pugi::xml_node wrap_set = points_owner.child("PathWrapSet");
  if (!wrap_set) wrap_set = points_owner.child("MuscleWrapSet");
  for (pugi::xml_node node : ObjectsOf(wrap_set)) {
    model::PathWrapSpec wrap;
    const std::string component = path_path + "/" + NameOf(node);
    wrap.wrap_object = TextOf(node, "wrap_object");
    wrap.method = TextOf(node, "method");
    if (wrap.method.empty()) wrap.method = "hybrid";
    if (pugi::xml_node range = node.child("range")) {
      std::vector<double> r = doc.ReadNumbers(range, component, 2, NumberRange::kAllowInfinite);
      for (int i = 0; i < 2; ++i) {
        // Path point numbers (1-based) or -1: whole numbers in int range (casting anything else
        // would be undefined behaviour).
        if (!(r[i] >= -1e9 && r[i] <= 1e9) || r[i] != std::floor(r[i])) {
          doc.Fail(range, component, "<range> expects two whole numbers (path point indices)");
        }
        wrap.range[i] = static_cast<int>(r[i]);
      }
    }
    if (!ctx.HasWrapObject(wrap.wrap_object)) {
      doc.Fail(node.child("wrap_object") ? node.child("wrap_object") : node, component,
               "wrap object '" + wrap.wrap_object + "' does not exist");
    }
    path.wraps.push_back(std::move(wrap));
  }
  return path;
}

// The element holding a force's path points: 4.x <GeometryPath> (directly or, 4.5+, inside
// <path>), 1.9 the force itself (MusclePointSet).
pugi::xml_node FindPathOwner(const pugi::xml_node& force) {
  if (pugi::xml_node path = force.child("GeometryPath")) return path;
  if (pugi::xml_node wrapper = force.child("path")) {
    if (pugi::xml_node path = wrapper.child("GeometryPath")) return path;
  }
  for (pugi::xml_node child : force.children()) {
    if (child.type() == pugi::node_element && std::string_view(child.name()) == "GeometryPath") {
      return child;
    }
  }
  if (force.child("MusclePointSet")) return force;
  return {};
}

// A force's FunctionBasedPath (4.5+): directly, or inside a <path> wrapper.
pugi::xml_node FindFunctionBasedPath(const pugi::xml_node& force) {
  if (pugi::xml_node path = force.child("FunctionBasedPath")) return path;
  if (pugi::xml_node wrapper = force.child("path")) return wrapper.child("FunctionBasedPath");
  return {};
}

// OpenSim's FunctionBasedPath with the checks of its extendFinalizeFromProperties: a length
// function, at least one coordinate and no coordinate twice, and functions taking as many
// arguments as there are coordinates (twice as many for the lengthening speed).
model::FunctionBasedPathSpec ReadFunctionBasedPath(ReadContext& ctx, const pugi::xml_node& node,
                                                   const std::string& component) {
  const XmlDocument& doc = ctx.doc();
  model::FunctionBasedPathSpec path;
  path.name = NameOf(node);
  path.where = doc.Where(node);
  pugi::xml_node coordinates = node.child("coordinate_paths");
  std::istringstream names(coordinates ? std::string(XmlDocument::Text(coordinates)) : "");
  for (std::string name; names >> name;) {
    const int c = ResolveCoordinateName(ctx, coordinates, name, component);
    if (std::find(path.coordinates.begin(), path.coordinates.end(), c) != path.coordinates.end()) {
      doc.Fail(coordinates, component, "coordinate '" + name + "' is listed more than once");
    }
    path.coordinates.push_back(c);
  }
  if (path.coordinates.empty()) {
    doc.Fail(coordinates ? coordinates : node, component,
             "FunctionBasedPath lists no coordinate in <coordinate_paths>");
  }
  const int n = static_cast<int>(path.coordinates.size());
  auto check_arguments = [&](const pugi::xml_node& where, const functions::Function& f,
                             const std::string& what, int expected) {
    if (f.NumArguments() != expected) {
      doc.Fail(where, component,
               what + " takes " + std::to_string(f.NumArguments()) + " argument(s), but " +
                   std::to_string(expected) + " are expected (" + std::to_string(n) +
                   " coordinate(s) in <coordinate_paths>)");
    }
  };
  pugi::xml_node length = FindFunctionProperty(node, "length_function");
  if (length) path.length_function = ReadFunctionProperty(doc, length, component);
  if (!path.length_function) {
    doc.Fail(length ? length : node, component, "FunctionBasedPath has no <length_function>");
  }
  check_arguments(length, *path.length_function, "<length_function>", n);
  if (pugi::xml_node arms = node.child("moment_arm_functions")) {
    for (pugi::xml_node child : arms.children()) {
      if (child.type() != pugi::node_element) continue;
      path.moment_arm_functions.push_back(ReadFunction(doc, child, component));
      check_arguments(child, *path.moment_arm_functions.back(), "a moment arm function", n);
    }
    if (!path.moment_arm_functions.empty() &&
        static_cast<int>(path.moment_arm_functions.size()) != n) {
      doc.Fail(arms, component,
               "<moment_arm_functions> has " + std::to_string(path.moment_arm_functions.size()) +
                   " function(s) but there are " + std::to_string(n) + " coordinate(s)");
    }
  }
  if (pugi::xml_node speed = FindFunctionProperty(node, "lengthening_speed_function")) {
    path.lengthening_speed_function = ReadFunctionProperty(doc, speed, component);
    if (path.lengthening_speed_function) {
      check_arguments(speed, *path.lengthening_speed_function, "<lengthening_speed_function>",
                      2 * n);
    }
  }
  return path;
}

}  // namespace

void ReadForces(ReadContext& ctx, const pugi::xml_node& model) {
  ReadForceSet(ctx, model.child("ForceSet"), ctx.spec().version);
}

void ReadForceSet(ReadContext& ctx, const pugi::xml_node& force_set, int version) {
  const XmlDocument& doc = ctx.doc();
  for (pugi::xml_node node : ObjectsOf(force_set)) {
    model::ForceSpec force;
    force.name = NameOf(node);
    force.type = node.name();
    force.path = "/forceset/" + force.name;
    force.applies_force =
        ReadEnabledFlag(doc, node, "appliesForce", force.path, force.applies_force);
    if (pugi::xml_node owner = FindPathOwner(node)) {
      std::string name = owner == node ? "geometrypath" : NameOf(owner);
      if (name.empty()) name = "geometrypath";
      force.geometry_path = ReadGeometryPath(ctx, owner, force.path + "/" + name);
    } else if (pugi::xml_node function_path = FindFunctionBasedPath(node)) {
      std::string name = NameOf(function_path);
      if (name.empty()) name = "path";
      force.function_based_path =
          ReadFunctionBasedPath(ctx, function_path, force.path + "/" + name);
    } else {
      // Other path kinds (4.6 Scholz2015GeometryPath): kept, not read.
      for (pugi::xml_node child : node.children()) {
        const std::string_view tag = child.name();
        if (child.type() == pugi::node_element && tag.size() >= 4 &&
            (tag.substr(tag.size() - 4) == "Path")) {
          ctx.Warn(child, force.path,
                   "path of type <" + std::string(tag) + "> kept in the element, not read",
                   "path:" + std::string(tag));
        }
      }
    }
    // CoordinateActuator, CoordinateLimitForce, ...: the coordinate must exist.
    if (pugi::xml_node coordinate = node.child("coordinate")) {
      if (!XmlDocument::Text(coordinate).empty()) ResolveCoordinate(ctx, coordinate, force.path);
    }
    ReadForceAttachments(ctx, node, force);
    force.element = ToElement(doc, node);
    force.where = doc.Where(node);
    force.version = version;
    ctx.spec().forces.push_back(std::move(force));
  }
}

}  // namespace sinew::io::internal

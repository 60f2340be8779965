// What the force builders share: bodies, coordinates and frames named by a force, mapped from
// the spec to the engine.
#include <sinew/model/element_values.h>
#include <sinew/opensim/internal/force_registry.h>

namespace sinew::opensim::internal {

std::string LastPathSegment(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

int MapBody(const model::ModelSpec& spec, const model::ElementValues& values,
            const std::string& name, const std::vector<int>& body_map, const char* property) {
  const int b = spec.FindBody(LastPathSegment(name));
  if (b == model::kNone)
    values.Fail(std::string(property) + " '" + name + "' is not a body of the model");
  return body_map[b];
}

PointsOnBodies MapPointsOnBodies(const ForceBuildInput& in) {
  const model::ElementValues& v = in.values;
  PointsOnBodies p;
  p.body1 = MapBody(in.spec, v, v.FirstString({"socket_body1", "body1"}).value_or(""), in.body_map,
                    "body1");
  p.body2 = MapBody(in.spec, v, v.FirstString({"socket_body2", "body2"}).value_or(""), in.body_map,
                    "body2");
  p.point1 = v.Vector3("point1", Vec3::Zero());
  p.point2 = v.Vector3("point2", Vec3::Zero());
  return p;
}

int SpecCoordinate(const ForceBuildInput& in) {
  const model::ElementValues& v = in.values;
  const std::string name =
      LastPathSegment(v.FirstString({"coordinate", "socket_coordinate"}).value_or(""));
  const int c = in.spec.FindCoordinate(name);
  if (c == model::kNone) v.Fail("coordinate '" + name + "' is not a coordinate of the model");
  if (in.coordinate_map[c] == model::kNone)
    v.Fail("coordinate '" + name + "' belongs to no simulated joint");
  return c;
}

std::pair<int, Transform> MapFrame(const ForceBuildInput& in, const std::string& socket) {
  const auto it = in.force.frames.find(socket);
  if (it == in.force.frames.end()) {
    in.values.Fail("names no frame '" + socket + "' (<socket_" + socket + ">" +
                   (socket == "frame" ? "" : " or 3.x <body_" + socket.substr(5) + ">") + ")");
  }
  return {in.body_map[it->second.body], it->second.X_BF};
}

std::shared_ptr<const forces::Expression> ParseExpression(
    const ForceBuildInput& in, const char* tag, const std::string& fallback,
    const std::vector<std::string>& variables) {
  const model::Element* property = in.force.element.Child(tag);
  try {
    return std::make_shared<const forces::Expression>(property ? property->text : fallback,
                                                      variables);
  } catch (const Error& error) {
    in.values.Fail("<" + std::string(tag) + "> " + error.message(), property ? property->line : 0);
  }
}

}  // namespace sinew::opensim::internal

#include <sinew/engine/frame_constraint.h>
#include <sinew/forces/constant_distance_constraint.h>
#include <sinew/forces/coordinate_coupler_constraint.h>
#include <sinew/forces/point_on_line_constraint.h>
#include <sinew/opensim/internal/constraint_registry.h>

#include <array>
#include <map>
#include <utility>

namespace sinew::opensim::internal {
namespace {

// True when the speed of coordinate `index` of a joint of this type is its coordinate rate
// (qdot = u). Not for Ball and Ellipsoid angles, nor for the rotations of Free and
// Scapulothoracic joints: their speeds are angular-velocity components.
bool SpeedIsRate(model::JointType type, int index) {
  switch (type) {
    case model::JointType::kBall:
    case model::JointType::kEllipsoid:
      return false;
    case model::JointType::kFree:
    case model::JointType::kScapulothoracic:
      return index >= 3;
    default:
      return true;
  }
}

std::vector<int> CouplerCoordinates(const model::ConstraintSpec& c) {
  std::vector<int> all = c.independent_coordinates;
  if (c.dependent_coordinate != model::kNone) all.push_back(c.dependent_coordinate);
  return all;
}

// The engine coordinate of spec coordinate `c`, failing when the engine cannot couple it.
int CoupledCoordinate(const ConstraintBuildInput& in, int c) {
  const model::CoordinateSpec& coordinate = in.spec.coordinates[c];
  if (coordinate.joint == model::kNone || in.coordinate_map[c] == model::kNone) {
    in.values.Fail("couples '" + coordinate.name + "', which belongs to no simulated joint");
  }
  const model::JointSpec& joint = in.spec.joints[coordinate.joint];
  int index = 0;
  while (joint.coordinates[index] != c) ++index;
  if (!SpeedIsRate(joint.kind, index)) {
    in.values.Fail("couples '" + coordinate.name + "' of " + joint.type + " " + joint.name +
                   ", whose speed is an angular velocity, not the coordinate's rate: not "
                   "supported");
  }
  return in.coordinate_map[c];
}

// Makes a T, turning its constructor's errors into errors at the constraint's file and line.
template <class T, class... Args>
std::shared_ptr<engine::Constraint> Make(const ConstraintBuildInput& in, Args&&... args) {
  try {
    return std::make_shared<T>(std::forward<Args>(args)...);
  } catch (const Error& error) {
    in.values.Fail(error.message());
  }
}

std::shared_ptr<engine::Constraint> BuildCoordinateCoupler(const ConstraintBuildInput& in) {
  const model::ConstraintSpec& c = in.constraint;
  if (c.dependent_coordinate == model::kNone) in.values.Fail("has no dependent_coordinate_name");
  std::vector<int> independent;
  for (int i : c.independent_coordinates) independent.push_back(CoupledCoordinate(in, i));
  const int dependent = CoupledCoordinate(in, c.dependent_coordinate);
  return Make<forces::CoordinateCouplerConstraint>(in, c.name, std::move(independent), dependent,
                                                   c.function, c.scale_factor);
}

std::vector<int> NoCoordinates(const model::ConstraintSpec&) { return {}; }

// The engine bodies of a body-to-body constraint's two frames (ConstraintSpec::frames).
std::array<int, 2> FrameBodies(const ConstraintBuildInput& in) {
  for (const model::ConstraintFrame& frame : in.constraint.frames) {
    if (frame.body == model::kNone) in.values.Fail("names no frame for one of its two bodies");
  }
  const std::array<int, 2> bodies = {in.body_map[in.constraint.frames[0].body],
                                     in.body_map[in.constraint.frames[1].body]};
  if (bodies[0] == bodies[1]) {
    in.values.Fail("connects '" + in.constraint.frames[0].frame + "' and '" +
                   in.constraint.frames[1].frame + "', which are fixed to the same body");
  }
  return bodies;
}

// WeldConstraint: frame2 stays coincident with frame1 (6 equations).
std::shared_ptr<engine::Constraint> BuildWeld(const ConstraintBuildInput& in) {
  const std::array<int, 2> b = FrameBodies(in);
  const auto& f = in.constraint.frames;
  return std::make_shared<engine::FrameConstraint>(in.constraint.name, b[0], f[0].X_BF, b[1],
                                                   f[1].X_BF, engine::FrameConstraintKind::kWeld);
}

// PointConstraint: location_body_2 on body_2 stays at location_body_1 on body_1 (3 equations).
// As in OpenSim, the locations are in the frames of the bodies the sockets' frames are fixed
// to, also when a socket names an offset frame.
std::shared_ptr<engine::Constraint> BuildPoint(const ConstraintBuildInput& in) {
  const std::array<int, 2> b = FrameBodies(in);
  const model::ElementValues& v = in.values;
  return std::make_shared<engine::FrameConstraint>(
      in.constraint.name, b[0], Transform::Translation(v.Vector3("location_body_1", Vec3::Zero())),
      b[1], Transform::Translation(v.Vector3("location_body_2", Vec3::Zero())),
      engine::FrameConstraintKind::kPoint);
}

// PointOnLineConstraint: point_on_follower stays on the line through point_on_line along
// line_direction_vec, both fixed in the line body (2 equations).
std::shared_ptr<engine::Constraint> BuildPointOnLine(const ConstraintBuildInput& in) {
  const std::array<int, 2> b = FrameBodies(in);
  const model::ElementValues& v = in.values;
  return Make<forces::PointOnLineConstraint>(
      in, in.constraint.name, b[0], v.Vector3("line_direction_vec", Vec3::Zero()),
      v.Vector3("point_on_line", Vec3::Zero()), b[1], v.Vector3("point_on_follower", Vec3::Zero()));
}

// ConstantDistanceConstraint: location_body_1 and location_body_2 stay constant_distance apart.
std::shared_ptr<engine::Constraint> BuildConstantDistance(const ConstraintBuildInput& in) {
  const std::array<int, 2> b = FrameBodies(in);
  const model::ElementValues& v = in.values;
  if (!v.Has("constant_distance")) v.Fail("has no constant_distance");
  return Make<forces::ConstantDistanceConstraint>(
      in, in.constraint.name, b[0], v.Vector3("location_body_1", Vec3::Zero()), b[1],
      v.Vector3("location_body_2", Vec3::Zero()), v.Double("constant_distance", 1.0));
}

}  // namespace

const ConstraintType* FindConstraintType(const std::string& opensim_class) {
  static const std::map<std::string, ConstraintType, std::less<>> registry = {
      {"ConstantDistanceConstraint", {&BuildConstantDistance, &NoCoordinates}},
      {"CoordinateCouplerConstraint", {&BuildCoordinateCoupler, &CouplerCoordinates}},
      {"PointConstraint", {&BuildPoint, &NoCoordinates}},
      {"PointOnLineConstraint", {&BuildPointOnLine, &NoCoordinates}},
      {"WeldConstraint", {&BuildWeld, &NoCoordinates}},
  };
  const auto it = registry.find(opensim_class);
  return it == registry.end() ? nullptr : &it->second;
}

std::shared_ptr<engine::Constraint> BuildConstraint(const model::ModelSpec& spec,
                                                    const model::ConstraintSpec& constraint,
                                                    const std::vector<int>& body_map,
                                                    const std::vector<int>& coordinate_map) {
  const model::ElementValues values(constraint.element, spec.file, constraint.path);
  const ConstraintType* type = FindConstraintType(constraint.type);
  if (!type) values.Fail("'" + constraint.type + "' is not a constraint type Sinew simulates");
  return type->build(ConstraintBuildInput{spec, constraint, values, body_map, coordinate_map});
}

}  // namespace sinew::opensim::internal

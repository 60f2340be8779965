#include <sinew/forces/coordinate_coupler_constraint.h>
#include <sinew/opensim/internal/constraint_registry.h>

#include <map>

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

std::shared_ptr<engine::Constraint> BuildCoordinateCoupler(const ConstraintBuildInput& in) {
  const model::ConstraintSpec& c = in.constraint;
  if (c.dependent_coordinate == model::kNone) in.values.Fail("has no dependent_coordinate_name");
  std::vector<int> independent;
  for (int i : c.independent_coordinates) independent.push_back(CoupledCoordinate(in, i));
  const int dependent = CoupledCoordinate(in, c.dependent_coordinate);
  try {
    return std::make_shared<forces::CoordinateCouplerConstraint>(
        c.name, std::move(independent), dependent, c.function, c.scale_factor);
  } catch (const Error& error) {
    in.values.Fail(error.message());
  }
}

}  // namespace

const ConstraintType* FindConstraintType(const std::string& opensim_class) {
  static const std::map<std::string, ConstraintType, std::less<>> registry = {
      {"CoordinateCouplerConstraint", {&BuildCoordinateCoupler, &CouplerCoordinates}},
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

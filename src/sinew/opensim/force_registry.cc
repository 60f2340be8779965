#include <sinew/forces/actuator.h>
#include <sinew/forces/coordinate_limit_force.h>
#include <sinew/forces/point_to_point_spring.h>
#include <sinew/forces/spring_generalized_force.h>
#include <sinew/model/element_values.h>
#include <sinew/model/force_source.h>
#include <sinew/opensim/internal/external_force_builder.h>
#include <sinew/opensim/internal/force_registry.h>

#include <limits>
#include <map>

namespace sinew::opensim::internal {
namespace {

// Documents older than 1.9.5 named actuator bodies and directions differently. OpenSim's
// PointActuator and TorqueActuator::updateFromXMLNode rename those properties when present and,
// for every document of such a version, negate the direction (axis) read; the PointActuator's
// force_is_global defaults to true there. A ForceSet file without an OpenSimDocument root is
// such a document (version 10500): gait2354_CMC_Actuators.xml's residual actuators act
// opposite to their written directions in OpenSim, and so they do here.
constexpr int kRenamedActuatorVersion = 10905;

bool UpgradesActuator(const model::ForceSpec& force) {
  return force.version > 0 && force.version < kRenamedActuatorVersion;
}

std::shared_ptr<forces::Actuator> MakePointActuator(const ForceBuildInput& in) {
  const model::ModelSpec& spec = in.spec;
  const model::ElementValues& v = in.values;
  const std::vector<int>& body_map = in.body_map;
  const bool upgrade = UpgradesActuator(in.force);
  auto name = [&](const char* old_name, const char* new_name) {
    return upgrade && v.Has(old_name) ? old_name : new_name;
  };
  Vec3 direction = v.Vector3(name("direction_A", "direction"), Vec3::Zero());
  if (upgrade) direction = -direction;
  return std::make_shared<forces::PointActuator>(
      in.force.name, v.Double("optimal_force", 1.0),
      MapBody(spec, v, v.String(name("body_B", "body")), body_map, "body"),
      v.Vector3(name("point_B", "point"), Vec3::Zero()), v.Bool("point_is_global", false),
      direction, v.Bool("force_is_global", upgrade));
}

std::shared_ptr<forces::Actuator> MakeTorqueActuator(const ForceBuildInput& in) {
  const model::ModelSpec& spec = in.spec;
  const model::ElementValues& v = in.values;
  const std::vector<int>& body_map = in.body_map;
  const bool upgrade = UpgradesActuator(in.force);
  const std::string body_a = upgrade && v.Has("body_B")
                                 ? v.String("body_B")
                                 : v.FirstString({"bodyA", "socket_bodyA"}).value_or("");
  const std::string body_b = upgrade && v.Has("body_A")
                                 ? v.String("body_A")
                                 : v.FirstString({"bodyB", "socket_bodyB"}).value_or("");
  Vec3 axis = v.Vector3(upgrade && v.Has("direction_A") ? "direction_A" : "axis", Vec3(0, 0, 1));
  if (upgrade) axis = -axis;
  return std::make_shared<forces::TorqueActuator>(
      in.force.name, v.Double("optimal_force", 1.0), MapBody(spec, v, body_a, body_map, "bodyA"),
      MapBody(spec, v, body_b, body_map, "bodyB"), axis, v.Bool("torque_is_global", true));
}

std::shared_ptr<forces::Actuator> MakeCoordinateActuator(const ForceBuildInput& in) {
  return std::make_shared<forces::CoordinateActuator>(
      in.force.name, in.values.Double("optimal_force", 1.0), in.coordinate_map[SpecCoordinate(in)]);
}

std::shared_ptr<engine::ForceElement> BuildSpringGeneralizedForce(const ForceBuildInput& in) {
  const model::ElementValues& v = in.values;
  return std::make_shared<forces::SpringGeneralizedForce>(
      in.force.name, in.coordinate_map[SpecCoordinate(in)], v.Double("stiffness", 0.0),
      v.Double("rest_length", 0.0), v.Double("viscosity", 0.0));
}

std::shared_ptr<engine::ForceElement> BuildPointToPointSpring(const ForceBuildInput& in) {
  const PointsOnBodies p = MapPointsOnBodies(in);
  return std::make_shared<forces::PointToPointSpring>(in.force.name, p.body1, p.point1, p.body2,
                                                      p.point2, in.values.Double("stiffness", 1.0),
                                                      in.values.Double("rest_length", 0.0));
}

std::shared_ptr<engine::ForceElement> BuildCoordinateLimitForce(const ForceBuildInput& in) {
  const model::ElementValues& v = in.values;
  const int c = SpecCoordinate(in);
  forces::CoordinateLimitParameters p;
  p.upper_stiffness = v.Double("upper_stiffness", p.upper_stiffness);
  p.upper_limit = v.Double("upper_limit", p.upper_limit);
  p.lower_stiffness = v.Double("lower_stiffness", p.lower_stiffness);
  p.lower_limit = v.Double("lower_limit", p.lower_limit);
  p.damping = v.Double("damping", p.damping);
  p.transition = v.Double("transition", p.transition);
  const bool rotational = in.spec.coordinates[c].motion_type == model::MotionType::kRotational;
  try {
    return std::make_shared<forces::CoordinateLimitForce>(in.force.name, in.coordinate_map[c],
                                                          rotational, p);
  } catch (const Error& error) {
    v.Fail(error.message());
  }
}

// OpenSim's min_control / max_control, kept on the actuator for reporting.
template <std::shared_ptr<forces::Actuator> (*make)(const ForceBuildInput&)>
std::shared_ptr<engine::ForceElement> BuildActuator(const ForceBuildInput& in) {
  std::shared_ptr<forces::Actuator> actuator = make(in);
  constexpr double kInf = std::numeric_limits<double>::infinity();
  actuator->SetControlRange(in.values.Bound("min_control", -kInf),
                            in.values.Bound("max_control", kInf));
  return actuator;
}

}  // namespace

const ForceType* FindForceType(const std::string& opensim_class) {
  static const std::map<std::string, ForceType, std::less<>> registry = {
      {"PointActuator", {&BuildActuator<MakePointActuator>, true}},
      {"TorqueActuator", {&BuildActuator<MakeTorqueActuator>, true}},
      {"CoordinateActuator", {&BuildActuator<MakeCoordinateActuator>, true}},
      {"CoordinateLimitForce", {&BuildCoordinateLimitForce, false}},
      {"ExternalForce", {&BuildExternalForce, false}},
      {"PointToPointSpring", {&BuildPointToPointSpring, false}},
      {"SpringGeneralizedForce", {&BuildSpringGeneralizedForce, false}},
      {"BushingForce", {&BuildBushingForce, false}},
      {"FunctionBasedBushingForce", {&BuildFunctionBasedBushingForce, false}},
      {"ExpressionBasedBushingForce", {&BuildExpressionBasedBushingForce, false}},
      {"ExpressionBasedCoordinateForce", {&BuildExpressionBasedCoordinateForce, false}},
      {"ExpressionBasedPointToPointForce", {&BuildExpressionBasedPointToPointForce, false}},
      {"PrescribedForce", {&BuildPrescribedForce, false}},
      {"PathActuator", {&BuildPathActuator, true}},
      {"PathSpring", {&BuildPathSpring, false}},
      {"Blankevoort1991Ligament", {&BuildBlankevoortLigament, false}},
      {"Thelen2003Muscle", {&BuildThelen2003Muscle, true}},
      {"Thelen2003Muscle_Deprecated", {&BuildThelen2003MuscleDeprecated, true}},
      {"Millard2012EquilibriumMuscle", {&BuildMillard2012EquilibriumMuscle, true}},
      {"DeGrooteFregly2016Muscle", {&BuildDeGrooteFregly2016Muscle, true}},
      {"Schutte1993Muscle_Deprecated", {&BuildSchutte1993Muscle, true}},
      {"Schutte1993Muscle", {&BuildSchutte1993Muscle, true}},  // OpenSim renames it as above
      {"RigidTendonMuscle", {&BuildRigidTendonMuscle, true}},
      {"HuntCrossleyForce", {&BuildHuntCrossleyForce, false}},
      {"ElasticFoundationForce", {&BuildElasticFoundationForce, false}},
      {"SmoothSphereHalfSpaceForce", {&BuildSmoothSphereHalfSpaceForce, false}},
  };
  const auto it = registry.find(opensim_class);
  return it == registry.end() ? nullptr : &it->second;
}

std::shared_ptr<engine::ForceElement> BuildForce(
    const model::ModelSpec& spec, const model::ForceSpec& force, const std::vector<int>& body_map,
    const std::vector<int>& coordinate_map, const io::ExternalLoads* external_loads,
    Diagnostics* notes, bool equilibrate_muscles, paths::CylinderRefinement cylinder_refinement,
    const std::vector<std::string>* geometry_dirs) {
  const std::string& file = model::SourceFile(spec, force);
  const model::ElementValues values(force.element, file, force.path);
  const ForceType* type = FindForceType(force.type);
  if (!type) values.Fail("'" + force.type + "' is not a force type Sinew simulates");
  return type->build(ForceBuildInput{spec, force, values, body_map, coordinate_map, external_loads,
                                     notes, equilibrate_muscles, cylinder_refinement,
                                     geometry_dirs});
}

}  // namespace sinew::opensim::internal

// Spec -> engine for OpenSim's force classes: one registry from OpenSim class name to the
// builder that makes the engine force element. A new force type is one entry here (and its
// element in forces/); the parser, the list of what is not simulated and the Report all read
// this table.
#pragma once

#include <sinew/common/error.h>
#include <sinew/engine/force_element.h>
#include <sinew/forces/expression.h>
#include <sinew/io/external_loads.h>
#include <sinew/model/element_values.h>
#include <sinew/model/model_spec.h>
#include <sinew/paths/geometry_path.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace sinew::opensim::internal {

/// What a force builder reads: the spec, the force, its property values, and the maps from
/// spec bodies and coordinates to engine ones.
struct ForceBuildInput {
  const model::ModelSpec& spec;
  const model::ForceSpec& force;
  const model::ElementValues& values;
  const std::vector<int>& body_map;        ///< spec body index -> engine body index
  const std::vector<int>& coordinate_map;  ///< spec coordinate index -> engine coordinate index
  /// The ExternalLoads file the force comes from (its data), or null for a model's own force.
  const io::ExternalLoads* external_loads = nullptr;
  /// Where a builder notes what it read leniently, as OpenSim would (may be null).
  Diagnostics* notes = nullptr;
  /// Muscles start at muscle-tendon equilibrium (OpenSimParser::EquilibrateMuscles).
  bool equilibrate_muscles = false;
  /// Which OpenSim's rule path forces' cylinders follow (OpenSimParser::SetCylinderRefinement).
  paths::CylinderRefinement cylinder_refinement = paths::CylinderRefinement::kSeveralWraps;
  /// Folders searched for a ContactMesh's file after the model's own (the parser's
  /// AddGeometryDir); may be null.
  const std::vector<std::string>* geometry_dirs = nullptr;
};

/// How one OpenSim force class is built.
struct ForceType {
  /// Makes the engine element. Throws sinew::Error (file, line, force path) for unknown bodies
  /// or coordinates or malformed properties.
  std::shared_ptr<engine::ForceElement> (*build)(const ForceBuildInput& input);
  /// True for actuators (forces::Actuator: one excitation input, listed with its source).
  bool actuator = false;
};

// ---- what builders share (force_build_helpers.cc) ----

/// The engine index of the body `name` (a body name or a path ending in one) names; fails
/// naming `property` when the model has no such body.
int MapBody(const model::ModelSpec& spec, const model::ElementValues& values,
            const std::string& name, const std::vector<int>& body_map, const char* property);
/// Two points, each fixed to a body (engine indices; points in the body's frame).
struct PointsOnBodies {
  int body1 = 0;
  Vec3 point1 = Vec3::Zero();
  int body2 = 0;
  Vec3 point2 = Vec3::Zero();
};
/// The bodies a point-to-point force names (`body1`/`socket_body1`, `body2`/`socket_body2`)
/// and its `point1`, `point2`; fails naming the property when a body does not exist.
PointsOnBodies MapPointsOnBodies(const ForceBuildInput& in);
/// The spec index of the coordinate a force names in `coordinate` (3.x and 4.x) or
/// `socket_coordinate`; fails when it is not in the model or not simulated.
int SpecCoordinate(const ForceBuildInput& in);
/// The engine body and the pose in it (X_BF) of the frame the force's socket `socket` names
/// ("frame1", "frame2", "frame": ForceSpec::frames); fails when the force names none.
std::pair<int, Transform> MapFrame(const ForceBuildInput& in, const std::string& socket);
/// The formula in property `tag` (`fallback` when absent) in `variables`; a malformed one fails
/// at the property's line, naming the force.
std::shared_ptr<const forces::Expression> ParseExpression(
    const ForceBuildInput& in, const char* tag, const std::string& fallback,
    const std::vector<std::string>& variables);

// ---- builders defined beside their kind of force ----

/// BushingForce, FunctionBasedBushingForce, ExpressionBasedBushingForce (bushing_builders.cc).
std::shared_ptr<engine::ForceElement> BuildBushingForce(const ForceBuildInput& in);
std::shared_ptr<engine::ForceElement> BuildFunctionBasedBushingForce(const ForceBuildInput& in);
std::shared_ptr<engine::ForceElement> BuildExpressionBasedBushingForce(const ForceBuildInput& in);
/// ExpressionBasedCoordinateForce, ExpressionBasedPointToPointForce (expression_builders.cc).
std::shared_ptr<engine::ForceElement> BuildExpressionBasedCoordinateForce(
    const ForceBuildInput& in);
std::shared_ptr<engine::ForceElement> BuildExpressionBasedPointToPointForce(
    const ForceBuildInput& in);
/// PrescribedForce (prescribed_force_builder.cc).
std::shared_ptr<engine::ForceElement> BuildPrescribedForce(const ForceBuildInput& in);
/// PathActuator and the muscles (muscle_builders.cc): a muscles::PathActuator on the force's
/// GeometryPath with its tension model; PathSpring (muscles::PathSpring).
std::shared_ptr<engine::ForceElement> BuildPathActuator(const ForceBuildInput& in);
std::shared_ptr<engine::ForceElement> BuildPathSpring(const ForceBuildInput& in);
/// Blankevoort1991Ligament (muscles::BlankevoortLigament) on its GeometryPath.
std::shared_ptr<engine::ForceElement> BuildBlankevoortLigament(const ForceBuildInput& in);
std::shared_ptr<engine::ForceElement> BuildThelen2003Muscle(const ForceBuildInput& in);
std::shared_ptr<engine::ForceElement> BuildThelen2003MuscleDeprecated(const ForceBuildInput& in);
std::shared_ptr<engine::ForceElement> BuildMillard2012EquilibriumMuscle(const ForceBuildInput& in);
std::shared_ptr<engine::ForceElement> BuildDeGrooteFregly2016Muscle(const ForceBuildInput& in);
std::shared_ptr<engine::ForceElement> BuildSchutte1993Muscle(const ForceBuildInput& in);
std::shared_ptr<engine::ForceElement> BuildRigidTendonMuscle(const ForceBuildInput& in);
/// HuntCrossleyForce, ElasticFoundationForce, SmoothSphereHalfSpaceForce (contact_builders.cc).
std::shared_ptr<engine::ForceElement> BuildHuntCrossleyForce(const ForceBuildInput& in);
std::shared_ptr<engine::ForceElement> BuildElasticFoundationForce(const ForceBuildInput& in);
std::shared_ptr<engine::ForceElement> BuildSmoothSphereHalfSpaceForce(const ForceBuildInput& in);

/// The entry for OpenSim class `opensim_class`, or null when Sinew does not simulate it.
const ForceType* FindForceType(const std::string& opensim_class);

/// The engine element of `force`, whose class must have a registry entry.
/// `external_loads`, `notes`, `equilibrate_muscles`, `cylinder_refinement` and
/// `geometry_dirs` as in ForceBuildInput.
std::shared_ptr<engine::ForceElement> BuildForce(
    const model::ModelSpec& spec, const model::ForceSpec& force, const std::vector<int>& body_map,
    const std::vector<int>& coordinate_map, const io::ExternalLoads* external_loads = nullptr,
    Diagnostics* notes = nullptr, bool equilibrate_muscles = false,
    paths::CylinderRefinement cylinder_refinement = paths::CylinderRefinement::kSeveralWraps,
    const std::vector<std::string>* geometry_dirs = nullptr);

/// The last segment of a socket path ("/bodyset/rod1" -> "rod1"), or the name itself.
std::string LastPathSegment(const std::string& path);

}  // namespace sinew::opensim::internal

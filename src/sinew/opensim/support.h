// What the simulator handles yet: the list of spec elements that are read and kept but not
// simulated, shown by `sinew inspect`, the build Report and every `sinew` run, and the stand-in
// that replaces a joint the engine cannot model. Shrinks as the engine grows.
#pragma once

#include <sinew/model/model_spec.h>

#include <string>
#include <vector>

namespace sinew::opensim {

/// True if the engine can build this joint (a type the kinematics models; see
/// kinematics::IsJointTypeModeled). A joint that is not is replaced by a stand-in.
bool IsJointSimulated(const model::JointSpec& joint);
/// True if the engine simulates this force (its class is in the force registry and it is on).
bool IsForceSimulated(const model::ForceSpec& force);
/// True if the engine enforces this constraint (its class is in the constraint registry, e.g.
/// CoordinateCouplerConstraint, and it is enforced).
bool IsConstraintSimulated(const model::ConstraintSpec& constraint);
/// True if the engine runs controllers of this OpenSim class (PrescribedController).
bool IsControllerSimulated(const model::ControllerSpec& controller);
/// True if a simulated contact force of `spec` (HuntCrossleyForce, ElasticFoundationForce,
/// SmoothSphereHalfSpaceForce) names this contact geometry.
bool IsContactGeometrySimulated(const model::ModelSpec& spec,
                                const model::ContactGeometrySpec& contact);
/// True if paths wrap over wrap objects of this class (paths::IsWrapSurfaceSupported:
/// WrapCylinder, WrapSphere, WrapEllipsoid).
bool IsWrapObjectSimulated(const model::WrapObjectSpec& wrap);

/// The kinds of element counted in a summary of what is not simulated.
enum class ElementKind {
  kJoint,            ///< A joint the engine cannot build (a stand-in replaces it).
  kMuscle,           ///< A force whose OpenSim class ends in "Muscle".
  kForce,            ///< Any other force.
  kConstraint,       ///< A constraint.
  kController,       ///< A controller.
  kContactGeometry,  ///< Contact geometry.
  kWrapObject,       ///< A wrap object.
  kOther,            ///< Another component (a probe, an unknown set).
};

/// One element the simulator does not handle.
struct NotSimulatedElement {
  ElementKind kind = ElementKind::kOther;
  std::string path;  ///< e.g. "/forceset/biceps"
  std::string type;  ///< The OpenSim class, e.g. "Thelen2003Muscle".
};

/// Every element the simulator does not handle yet, in model order: joints, forces (not those
/// with appliesForce false: OpenSim does not apply them either), constraints, controllers,
/// contact geometry, wrap objects, other components.
/// Forces named in `disabled_forces` (OpenSimParser::DisableForce) are left out of the list too.
std::vector<NotSimulatedElement> FindNotSimulated(
    const model::ModelSpec& spec, const std::vector<std::string>& disabled_forces = {});

/// FindNotSimulated as lines "<path>: <OpenSim class>" (e.g. "/forceset/biceps:
/// Thelen2003Muscle"), in the same order.
std::vector<std::string> ListNotSimulated(const model::ModelSpec& spec,
                                          const std::vector<std::string>& disabled_forces = {});

/// The counts of `elements` by kind as an English list, kinds in ElementKind order:
/// "6 muscles, 4 wrap objects and 1 constraint"; "" for none. Forces are "other forces"
/// when muscles are also listed.
std::string CountByKind(const std::vector<NotSimulatedElement>& elements);

/// A joint replaced by a stand-in, and the coordinates it had (now attached to no joint).
struct StandIn {
  int joint = model::kNone;      ///< Index into ModelSpec::joints.
  std::vector<int> coordinates;  ///< Its former coordinates (indices into ModelSpec::coordinates).
};

/// Replaces every joint that is not simulated (IsJointSimulated false) by a spherical stand-in:
/// a BallJoint at the same frames with three new rotational coordinates
/// "<joint>_standin_rx|ry|rz" (path "<joint path>/<name>", zero: frames F and M coincide). The
/// joint keeps its name, path and `type`; its former coordinates stay in the spec with no joint.
/// This is the one place that decides what a stand-in is: the parser, `sinew inspect`,
/// `kinematics`, `simulate`, `export` and `render` all use it. Returns the joints replaced, in
/// joint order.
std::vector<StandIn> ReplaceWithStandIns(model::ModelSpec& spec);

}  // namespace sinew::opensim

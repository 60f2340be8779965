// What the simulator handles yet: the list of spec elements that are read and kept but not
// simulated, shown by `sinew inspect` and the build Report. Shrinks as the engine grows.
#pragma once

#include <string>
#include <vector>

#include <sinew/model/model_spec.h>

namespace sinew::opensim {

/// True if the engine can build this joint (every type Sinew knows; not kUnknown).
bool IsJointSimulated(const model::JointSpec& joint);
/// True if the engine simulates this force (PointActuator, TorqueActuator, CoordinateActuator).
bool IsForceSimulated(const model::ForceSpec& force);
/// True if the engine enforces constraints of this OpenSim class (none yet).
bool IsConstraintSimulated(const model::ConstraintSpec& constraint);
/// True if the engine runs controllers of this OpenSim class (PrescribedController).
bool IsControllerSimulated(const model::ControllerSpec& controller);
/// True if the engine uses contact geometry of this OpenSim class (none yet).
bool IsContactGeometrySimulated(const model::ContactGeometrySpec& contact);
/// True if the engine wraps paths over wrap objects of this class (none yet).
bool IsWrapObjectSimulated(const model::WrapObjectSpec& wrap);

/// One line per element the simulator does not handle yet, as "<path>: <OpenSim class>"
/// (e.g. "/forceset/biceps: Thelen2003Muscle"), in model order.
std::vector<std::string> ListNotSimulated(const model::ModelSpec& spec);

}  // namespace sinew::opensim

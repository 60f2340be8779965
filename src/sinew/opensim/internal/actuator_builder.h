// Spec -> engine for OpenSim's ideal actuators (PointActuator, TorqueActuator,
// CoordinateActuator).
#pragma once

#include <sinew/forces/actuator.h>
#include <sinew/model/model_spec.h>

#include <memory>
#include <vector>

namespace sinew::opensim::internal {

/// True for the actuator classes MakeActuator builds.
bool IsIdealActuator(const std::string& opensim_type);

/// The engine actuator of `force` (an ideal actuator), its bodies and coordinate mapped
/// through `body_map` / `coordinate_map` (spec index -> engine index). Its excitation is unset
/// (0). Throws sinew::Error (file, line, force path) for unknown bodies or coordinates or
/// malformed properties.
std::shared_ptr<forces::Actuator> MakeActuator(const model::ModelSpec& spec,
                                               const model::ForceSpec& force,
                                               const std::vector<int>& body_map,
                                               const std::vector<int>& coordinate_map);

}  // namespace sinew::opensim::internal

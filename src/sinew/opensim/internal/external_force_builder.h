// Spec -> engine for OpenSim's ExternalForce, from an ExternalLoads file or a model's ForceSet:
// its bodies, and the functions of time fitted through the columns its identifiers name.
#pragma once

#include <sinew/opensim/internal/force_registry.h>

#include <memory>

namespace sinew::opensim::internal {

/// The engine ExternalForce of `input` (its force registry entry). Its data: the ExternalLoads
/// file's `datafile` when input.external_loads is set; for a force in a model's ForceSet the
/// storage file `data_source_name` names, beside the model (OpenSim itself gives such a force
/// data only through ExternalLoads). Throws sinew::Error naming the file, the line and the
/// force for an unknown applied_to_body, an identifier that does not name exactly 3 columns,
/// no force and no torque, or missing data. force_expressed_in_body / point_expressed_in_body
/// naming no body fall back to ground with a note, as OpenSim does (a path naming no body, maybe
/// an offset frame, is an error).
std::shared_ptr<engine::ForceElement> BuildExternalForce(const ForceBuildInput& input);

}  // namespace sinew::opensim::internal

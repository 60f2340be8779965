// Millard2012EquilibriumMuscle from the model spec: its properties and curve properties as the
// file gives them, OpenSim's defaults for the rest.
#pragma once

#include <sinew/model/model_spec.h>
#include <sinew/muscles/millard2012_parameters.h>

#include <string>

namespace sinew::muscles {

/// The properties of the Millard2012EquilibriumMuscle `force` of `spec` (its element tree), with
/// OpenSim's defaults for absent ones. As OpenSim reads them: an empty optional curve property
/// (`<curviness />`) counts as absent, and in files older than format 30513 a min_control of 0
/// is dropped (older OpenSim wrote 0 there whatever the muscle's minimum_activation). Throws
/// sinew::Error naming the file, the property's line and the force for a malformed value.
Millard2012Parameters ReadMillard2012Parameters(const model::ModelSpec& spec,
                                                const model::ForceSpec& force);

/// The muscle those properties make; an impossible combination (one OpenSim refuses) is a
/// sinew::Error naming the file, the muscle's line and the force.
Millard2012Muscle ReadMillard2012Muscle(const model::ModelSpec& spec,
                                        const model::ForceSpec& force);

}  // namespace sinew::muscles

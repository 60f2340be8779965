// Millard2012EquilibriumMuscle from the model spec: its properties and curve properties as the
// file gives them, OpenSim's defaults for the rest.
#pragma once

#include <sinew/model/model_spec.h>
#include <sinew/muscles/millard2012_parameters.h>

#include <string>

namespace sinew::muscles {

/// The properties of the Millard2012EquilibriumMuscle `force` (its element tree, read from
/// `file`), with OpenSim's defaults for absent ones; an empty optional curve property
/// (`<curviness />`) counts as absent, as in OpenSim. Throws sinew::Error naming the file, the
/// property's line and the force for a malformed value.
Millard2012Parameters ReadMillard2012Parameters(const model::ForceSpec& force,
                                                const std::string& file);

/// The muscle those properties make; an impossible combination (one OpenSim refuses) is a
/// sinew::Error naming the file, the muscle's line and the force.
Millard2012Muscle ReadMillard2012Muscle(const model::ForceSpec& force, const std::string& file);

}  // namespace sinew::muscles

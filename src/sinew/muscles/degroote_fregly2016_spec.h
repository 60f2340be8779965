// DeGrooteFregly2016Muscle from the model spec: its properties as the file gives them, OpenSim's
// defaults for the rest.
#pragma once

#include <sinew/model/model_spec.h>
#include <sinew/muscles/degroote_fregly2016_muscle.h>

#include <string>

namespace sinew::muscles {

/// The muscle `force` of `spec` describes. A malformed value, an optimal_force other
/// than 1 (OpenSim ignores it for this muscle and refuses a changed one) or properties OpenSim
/// refuses are a sinew::Error naming the file, the line and the force.
DeGrooteFregly2016Muscle ReadDeGrooteFregly2016Muscle(const model::ModelSpec& spec,
                                                      const model::ForceSpec& force);

}  // namespace sinew::muscles

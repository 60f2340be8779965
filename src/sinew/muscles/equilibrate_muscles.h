// Muscle-tendon equilibrium of every muscle of a System at a State, on request (OpenSim's
// Model::equilibrateMuscles), whether or not the model was built to equilibrate at its start.
#pragma once

#include <sinew/engine/state.h>
#include <sinew/engine/system.h>
#include <sinew/muscles/tension_model.h>

#include <string>
#include <vector>

namespace sinew::muscles {

/// A muscle whose equilibrium is not a balance of its forces (TensionModel::Equilibrate's
/// status other than kBalanced).
struct UnbalancedMuscle {
  std::string component;  ///< e.g. "/forceset/TRIlong"
  EquilibriumStatus status = EquilibriumStatus::kBalanced;
  double fiber_length = 0.0;  ///< m, where it was put (NaN for a model without one)
};

/// Sets the fiber state of every muscle (PathActuator with state variables) in `state` to its
/// equilibrium at the state's pose, speeds and activations. Returns the muscles left
/// unbalanced, in force order. Throws sinew::Error naming the muscle when one has no
/// equilibrium.
std::vector<UnbalancedMuscle> EquilibrateMuscles(const engine::System& system,
                                                 engine::State& state);

/// What a user is told of an unbalanced muscle: "<component>: <why>, <fiber length> m".
std::string DescribeUnbalancedMuscle(const UnbalancedMuscle& muscle);

}  // namespace sinew::muscles

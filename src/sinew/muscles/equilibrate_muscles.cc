#include <sinew/muscles/equilibrate_muscles.h>
#include <sinew/muscles/path_actuator.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace sinew::muscles {

std::vector<UnbalancedMuscle> EquilibrateMuscles(const engine::System& system,
                                                 engine::State& state) {
  std::vector<UnbalancedMuscle> unbalanced;
  const auto& forces = system.force_elements();
  for (size_t k = 0; k < forces.size(); ++k) {
    const auto* muscle = dynamic_cast<const PathActuator*>(forces[k].get());
    if (muscle == nullptr || muscle->StateVariableNames().empty()) continue;
    const int index = static_cast<int>(k);
    const engine::ForceContext context = system.MakeForceContext(index, state);
    VecX z = state.z.segment(context.z_begin, system.NumStateVariables(index));
    const std::string& component = muscle->path().path().component();
    const EquilibriumStatus status =
        muscle->model().Equilibrate(muscle->CalcPathKinematics(context), component, z);
    state.z.segment(context.z_begin, z.size()) = z;
    if (status != EquilibriumStatus::kBalanced) {
      const std::vector<std::string> names = muscle->StateVariableNames();
      const auto fiber = std::find(names.begin(), names.end(), "fiber_length");
      unbalanced.push_back(
          {component, status, fiber == names.end() ? std::nan("") : z[fiber - names.begin()]});
    }
  }
  return unbalanced;
}

std::string DescribeUnbalancedMuscle(const UnbalancedMuscle& muscle) {
  std::ostringstream out;
  out << muscle.component << ": ";
  if (muscle.status == EquilibriumStatus::kFiberAtMinimumLength) {
    out << "no fiber length balances the tendon (even the shortest fiber pulls harder): the "
           "fiber starts at its minimum length, ";
  } else {
    out << "OpenSim's equilibrium iteration ended with the tendon at its slack length and the "
           "forces still more than 0.01 N apart: the fiber starts with the rest of the path, as "
           "in OpenSim, ";
  }
  out << muscle.fiber_length << " m";
  return out.str();
}

}  // namespace sinew::muscles

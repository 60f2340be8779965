#include <sinew/engine/reactions.h>
#include <sinew/opensim/constraint_forces_table.h>

namespace sinew::opensim {

std::vector<std::string> ConstraintForcesLabels(const engine::System& system) {
  std::vector<std::string> labels;
  const auto& constraints = system.constraints();
  for (size_t k = system.FirstExtraConstraint(); k < constraints.size(); ++k) {
    const std::string name = constraints[k]->name();
    for (int b : constraints[k]->Bodies()) {
      const std::string prefix = name + "_" + system.bodies()[b].name + "_";
      for (const char* component : {"Fx", "Fy", "Fz", "Mx", "My", "Mz"}) {
        labels.push_back(prefix + component);
      }
    }
    const size_t coordinates = constraints[k]->Coordinates().size();
    for (size_t i = 0; i < coordinates; ++i) {
      labels.push_back(name + "_mobility_F" + std::to_string(i));
    }
  }
  return labels;
}

void ConstraintForcesRow(const engine::System& system, const engine::State& state,
                         const engine::Loads* external, engine::Data& data,
                         std::vector<double>& row) {
  row.clear();
  const engine::Accelerations& accelerations =
      engine::CalcAccelerations(system, state, external, data);
  const int count = static_cast<int>(system.constraints().size());
  for (int k = system.FirstExtraConstraint(); k < count; ++k) {
    const engine::ConstraintLoads loads =
        engine::CalcConstraintLoads(system, state, accelerations, data.kkt, k);
    // OpenSim reports the negated loads, forces before moments.
    for (const SpatialVec& load : loads.on_bodies) {
      for (int i = 0; i < 3; ++i) row.push_back(-load[3 + i]);
      for (int i = 0; i < 3; ++i) row.push_back(-load[i]);
    }
    for (double f : loads.on_coordinates) row.push_back(-f);
  }
}

}  // namespace sinew::opensim

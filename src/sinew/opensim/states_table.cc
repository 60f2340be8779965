#include <sinew/opensim/states_table.h>

namespace sinew::opensim {

std::vector<std::string> StatesLabels(const engine::System& system) {
  std::vector<std::string> labels;
  // The system's coordinates, in its order (a stand-in joint's are its own, not the file's).
  for (const engine::Coordinate& c : system.coordinates()) {
    const std::string base = "/jointset/" + system.joints()[c.joint].name + "/" + c.name;
    labels.push_back(base + "/value");
    labels.push_back(base + "/speed");
  }
  for (const std::string& z : system.state_variable_names()) labels.push_back("/forceset/" + z);
  return labels;
}

void StatesRow(const engine::System& system, const engine::State& state, std::vector<double>& row) {
  row.resize(2 * static_cast<size_t>(system.num_coordinates()) +
             static_cast<size_t>(state.z.size()));
  size_t i = 0;
  for (int c = 0; c < system.num_coordinates(); ++c) {
    row[i++] = state.q[c];
    row[i++] = state.u[c];
  }
  for (int k = 0; k < state.z.size(); ++k) row[i++] = state.z[k];
}

std::vector<std::string> ControlsLabels(const engine::System& system) {
  std::vector<std::string> labels;
  for (int k = 0; k < static_cast<int>(system.force_elements().size()); ++k) {
    const int n = system.NumInputs(k);
    for (int i = 0; i < n; ++i) {
      labels.push_back(n == 1 ? system.force_elements()[k]->name()
                              : system.input_names()[system.InputBegin(k) + i]);
    }
  }
  return labels;
}

void ControlsRow(const engine::State& state, std::vector<double>& row) {
  row.assign(state.inputs.data(), state.inputs.data() + state.inputs.size());
}

}  // namespace sinew::opensim

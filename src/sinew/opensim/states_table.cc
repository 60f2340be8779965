#include <sinew/opensim/states_table.h>

#include <algorithm>

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

int FindStateVariableColumn(const engine::System& system, const std::string& label) {
  std::string name = label;
  constexpr std::string_view kForceSet = "/forceset/";
  if (name.starts_with(kForceSet)) {
    name = name.substr(kForceSet.size());
  } else if (const size_t dot = name.rfind('.');
             dot != std::string::npos && name.find('/') == std::string::npos) {
    name[dot] = '/';
  }
  const std::vector<std::string>& names = system.state_variable_names();
  const auto it = std::find(names.begin(), names.end(), name);
  return it == names.end() ? -1 : static_cast<int>(it - names.begin());
}

}  // namespace sinew::opensim

#include <sinew/common/error.h>
#include <sinew/common/text.h>
#include <sinew/io/storage_labels.h>
#include <sinew/opensim/initial_states.h>
#include <sinew/opensim/states_table.h>
#include <sinew/opensim/support.h>

#include <algorithm>
#include <cmath>
#include <string_view>

namespace sinew::opensim {
namespace {

// The force a state-variable column belongs to: "/forceset/<force>/<variable>" (OpenSim 4) or
// "<force>.<variable>" (OpenSim 3); "" for other labels.
std::string ForceOfStateColumn(std::string_view label) {
  constexpr std::string_view kPrefix = "/forceset/";
  if (label.starts_with(kPrefix)) {
    label.remove_prefix(kPrefix.size());
    const size_t slash = label.find('/');
    return slash == std::string_view::npos ? "" : std::string(label.substr(0, slash));
  }
  const size_t dot = label.rfind('.');
  return dot == std::string_view::npos || dot == 0 ? "" : std::string(label.substr(0, dot));
}

}  // namespace

int ForwardStartRow(const io::Storage& storage, double t) {
  int row = 0;
  while (row + 1 < storage.NumRows() && !(t < storage.time[row + 1])) ++row;
  return row;
}

InitialStates ApplyInitialStates(io::Storage& storage, const std::string& storage_path,
                                 model::ModelSpec& spec, int row) {
  if (storage.NumRows() == 0) {
    throw Error({storage_path, 0}, "", "the initial-states file has no rows");
  }
  std::vector<std::string> rotational, simulated;
  for (const model::CoordinateSpec& c : spec.coordinates) {
    if (c.joint == model::kNone || !IsJointSimulated(spec.joints[c.joint])) continue;
    simulated.push_back(c.name);
    if (c.motion_type == model::MotionType::kRotational) rotational.push_back(c.name);
  }
  InitialStates result;
  result.t0 = storage.time[row];
  // Columns of the state variables of simulated forces are used too (ApplyInitialStateVariables).
  std::vector<std::string> simulated_forces;
  for (const model::ForceSpec& force : spec.forces) {
    if (IsForceSimulated(force)) simulated_forces.push_back(force.name);
  }
  for (const std::string& label : storage.labels) {
    if (io::ParseColumnLabel(label, simulated)) continue;
    const std::string force = ForceOfStateColumn(label);
    if (!force.empty() && std::find(simulated_forces.begin(), simulated_forces.end(), force) !=
                              simulated_forces.end()) {
      continue;
    }
    result.unused_labels.push_back(label);
  }
  io::ConvertDegreesToRadians(storage, rotational);
  for (model::CoordinateSpec& c : spec.coordinates) {
    const int value = io::FindCoordinateColumn(storage, c.name, io::CoordinateColumnKind::kValue);
    const int speed = io::FindCoordinateColumn(storage, c.name, io::CoordinateColumnKind::kSpeed);
    if (value >= 0) c.default_value = storage.Value(row, value);
    if (speed >= 0) c.default_speed_value = storage.Value(row, speed);
    const bool is_simulated =
        std::find(simulated.begin(), simulated.end(), c.name) != simulated.end();
    if (is_simulated && value < 0) result.missing.push_back(c.name + " (value)");
    if (is_simulated && speed < 0) result.missing.push_back(c.name + " (speed)");
  }
  return result;
}

std::vector<std::string> ApplyInitialStateVariables(const io::Storage& storage, int row,
                                                    const std::string& storage_path,
                                                    const engine::System& system,
                                                    engine::State& state) {
  std::vector<bool> given(system.num_state_variables(), false);
  for (int column = 0; column < storage.NumColumns(); ++column) {
    const int k = FindStateVariableColumn(system, storage.labels[column]);
    if (k < 0) continue;
    const double value = storage.Value(row, column);
    if (!std::isfinite(value)) {
      throw Error({storage_path, 0}, system.state_variable_names()[k],
                  "column '" + storage.labels[column] + "' at time " +
                      FormatNumber(storage.time[row]) + " holds " + FormatNumber(value) +
                      ", not a finite number");
    }
    state.z[k] = value;
    given[k] = true;
  }
  std::vector<std::string> missing;
  for (int k = 0; k < system.num_state_variables(); ++k) {
    if (!given[k]) missing.push_back(system.state_variable_names()[k]);
  }
  return missing;
}

}  // namespace sinew::opensim

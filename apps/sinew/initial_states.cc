#include "apps/sinew/initial_states.h"

#include <sinew/common/error.h>
#include <sinew/opensim/initial_states.h>
#include <sinew/opensim/states_table.h>
#include <sinew/opensim/support.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string_view>
#include <vector>

#include "apps/sinew/notices.h"
#include "apps/sinew/tables.h"

namespace sinew::cli {
namespace {

// The row OpenSim's Forward tool starts from (ForwardTool::determineInitialTimeFromStatesStorage
// with Storage::findIndex): the last row whose time is at or before `t`, or the first row.
int RowAtOrBefore(const io::Storage& table, double t) {
  int row = 0;
  while (row + 1 < table.NumRows() && !(t < table.time[row + 1])) ++row;
  return row;
}

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

// Tells when the run does not start at `start_time` (OpenSim moves its initial time too).
void NoteStartRow(const InitialStates& states, double start_time) {
  if (states.time() == start_time) return;
  std::cerr << "sinew: note: " << states.path << ": "
            << (start_time < states.table.time[0]
                    ? "the initial time " + ShowNumber(start_time) + " precedes the first row"
                    : "no row at the initial time " + ShowNumber(start_time))
            << "; the run starts at " << ShowNumber(states.time())
            << " s, the time of the row used, as OpenSim's Forward tool does\n";
}

}  // namespace

InitialStates ApplyInitialStates(const std::string& path, bool strict, model::ModelSpec& spec,
                                 std::optional<double> start_time) {
  InitialStates states{path, ReadTableFor(path, spec), 0};
  if (states.table.NumRows() == 0) {
    throw Error({path, 0}, "", "the initial-states file has no rows");
  }
  if (start_time) {
    states.row = RowAtOrBefore(states.table, *start_time);
    NoteStartRow(states, *start_time);
  }
  const opensim::InitialStates taken =
      opensim::ApplyInitialStates(states.table, path, spec, states.row);
  // Columns of the state variables of simulated forces (muscle activations, fiber lengths) are
  // used too, by ApplyInitialStateVariables once the System exists.
  std::vector<std::string> simulated_forces;
  for (const model::ForceSpec& force : spec.forces) {
    if (opensim::IsForceSimulated(force)) simulated_forces.push_back(force.name);
  }
  std::vector<std::string> unused;
  for (const std::string& label : taken.unused_labels) {
    const std::string force = ForceOfStateColumn(label);
    const bool of_simulated_force =
        !force.empty() && std::find(simulated_forces.begin(), simulated_forces.end(), force) !=
                              simulated_forces.end();
    if (!of_simulated_force) unused.push_back(label);
  }
  WarnUnusedColumns(unused, path,
                    "they name no coordinate value or speed or state variable that is simulated",
                    strict);
  if (!taken.missing.empty()) {
    std::cerr << "sinew: warning: " << path << ": " << taken.missing.size()
              << " coordinate values or speeds are not in the file (" << FirstFew(taken.missing)
              << "): they keep the model's defaults\n";
  }
  return states;
}

void ApplyInitialStateVariables(const InitialStates& states, const engine::System& system,
                                engine::State& state) {
  std::vector<bool> given(system.num_state_variables(), false);
  for (int column = 0; column < states.table.NumColumns(); ++column) {
    const int k = opensim::FindStateVariableColumn(system, states.table.labels[column]);
    if (k < 0) continue;
    const double value = states.table.Value(states.row, column);
    if (!std::isfinite(value)) {
      throw Error({states.path, 0}, system.state_variable_names()[k],
                  "column '" + states.table.labels[column] + "' at time " +
                      ShowNumber(states.time()) + " holds " + ShowNumber(value) +
                      ", not a finite number");
    }
    state.z[k] = value;
    given[k] = true;
  }
  std::vector<std::string> missing;
  for (int k = 0; k < system.num_state_variables(); ++k) {
    if (!given[k]) missing.push_back(system.state_variable_names()[k]);
  }
  if (!missing.empty()) {
    std::cerr << "sinew: warning: " << states.path << ": " << missing.size()
              << " state variables are not in the file (" << FirstFew(missing)
              << "): they keep their defaults\n";
  }
}

}  // namespace sinew::cli

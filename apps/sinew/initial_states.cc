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
    states.row = opensim::ForwardStartRow(states.table, *start_time);
    NoteStartRow(states, *start_time);
  }
  const opensim::InitialStates taken =
      opensim::ApplyInitialStates(states.table, path, spec, states.row);
  WarnUnusedColumns(taken.unused_labels, path,
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
  const std::vector<std::string> missing =
      opensim::ApplyInitialStateVariables(states.table, states.row, states.path, system, state);
  if (!missing.empty()) {
    std::cerr << "sinew: warning: " << states.path << ": " << missing.size()
              << " state variables are not in the file (" << FirstFew(missing)
              << "): they keep their defaults\n";
  }
}

}  // namespace sinew::cli

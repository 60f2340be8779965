#include "apps/sinew/initial_states.h"

#include <sinew/common/error.h>
#include <sinew/common/text.h>
#include <sinew/opensim/initial_states.h>

#include <iostream>
#include <vector>

#include "apps/sinew/notices.h"
#include "apps/sinew/tables.h"

namespace sinew::cli {
InitialStates ApplyInitialStates(const std::string& path, bool strict, model::ModelSpec& spec) {
  InitialStates states{path, ReadTableFor(path, spec), 0};
  ApplyInitialStates(states, strict, spec);
  return states;
}

void ApplyInitialStates(InitialStates& states, bool strict, model::ModelSpec& spec) {
  const std::string& path = states.path;
  if (states.table.NumRows() == 0) {
    throw Error({path, 0}, "", "the initial-states file has no rows");
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

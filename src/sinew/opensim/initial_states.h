// Initial states from a states table, as OpenSim's Forward tool takes them: the first row's
// coordinate values and speeds become the coordinates' defaults, so that locked coordinates are
// held at the table's value. Shared by `sinew simulate --initial-states` and Python's
// `model.simulate(initial_states=...)`.
#pragma once

#include <sinew/io/storage.h>
#include <sinew/model/model_spec.h>

#include <string>
#include <vector>

namespace sinew::opensim {

/// What ApplyInitialStates took from a table.
struct InitialStates {
  double t0 = 0.0;  ///< the time of the row used (s)
  /// Labels of the table that name no simulated coordinate's value or speed (muscle states,
  /// coordinates of stand-in joints): the caller reports them (an error when strict).
  std::vector<std::string> unused_labels;
  /// Simulated coordinates whose value or speed the table lacks ("<name> (value)", "<name>
  /// (speed)"): they keep the model's defaults.
  std::vector<std::string> missing;
};

/// Sets the default value and speed of every coordinate of `spec` that `storage` names (OpenSim
/// 4 paths or old names) from its row `row` (the first by default), rotational columns converted
/// to radians when the table is in degrees (the table is converted in place). Coordinates the
/// table does not name keep their defaults. Throws sinew::Error naming `storage_path` when the
/// table has no rows.
InitialStates ApplyInitialStates(io::Storage& storage, const std::string& storage_path,
                                 model::ModelSpec& spec, int row = 0);

}  // namespace sinew::opensim

// Initial states from a states table, as OpenSim's Forward tool takes them: the first row's
// coordinate values and speeds become the coordinates' defaults, so that locked coordinates are
// held at the table's value, and its state variables (muscle activations, fiber lengths) those
// of the state a run starts from. Shared by `sinew simulate --initial-states`, `sinew forward`
// and Python's `model.simulate(initial_states=...)`.
#pragma once

#include <sinew/engine/state.h>
#include <sinew/engine/system.h>
#include <sinew/io/storage.h>
#include <sinew/model/model_spec.h>

#include <string>
#include <vector>

namespace sinew::opensim {

/// What ApplyInitialStates took from a table.
struct InitialStates {
  double t0 = 0.0;  ///< the time of the row used (s)
  /// Labels of the table that name no simulated coordinate's value or speed nor a state
  /// variable of a simulated force (coordinates of stand-in joints, forces left out): the caller
  /// reports them (an error when strict).
  std::vector<std::string> unused_labels;
  /// Simulated coordinates whose value or speed the table lacks ("<name> (value)", "<name>
  /// (speed)"): they keep the model's defaults.
  std::vector<std::string> missing;
};

/// The row OpenSim's Forward tool starts a run at time `t` from
/// (ForwardTool::determineInitialTimeFromStatesStorage with Storage::findIndex): the last row
/// whose time is at or before `t`, or the first row when `t` precedes them all.
int ForwardStartRow(const io::Storage& storage, double t);

/// Sets the default value and speed of every coordinate of `spec` that `storage` names (OpenSim
/// 4 paths or old names) from its row `row` (the first by default), rotational columns converted
/// to radians when the table is in degrees (the table is converted in place). Coordinates the
/// table does not name keep their defaults. Throws sinew::Error naming `storage_path` when the
/// table has no rows.
InitialStates ApplyInitialStates(io::Storage& storage, const std::string& storage_path,
                                 model::ModelSpec& spec, int row = 0);

/// Sets the auxiliary state variables of `state` (of `system`) that row `row` of `storage`
/// names ("/forceset/<element>/<variable>" or OpenSim 3's "<element>.<variable>"). Returns the
/// names of the state variables the table does not name: they keep their values. Throws
/// sinew::Error naming `storage_path` and the state variable for a value that is not finite.
std::vector<std::string> ApplyInitialStateVariables(const io::Storage& storage, int row,
                                                    const std::string& storage_path,
                                                    const engine::System& system,
                                                    engine::State& state);

}  // namespace sinew::opensim

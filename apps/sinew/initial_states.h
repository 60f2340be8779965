// Initial states tables (.sto) for `simulate --initial-states` and the `states_file` of
// `forward` setups: one row gives the coordinates' values and speeds and the auxiliary state
// variables (muscle activations, fiber lengths, ...), as OpenSim's Forward tool reads them.
#pragma once

#include <sinew/engine/state.h>
#include <sinew/engine/system.h>
#include <sinew/io/storage.h>
#include <sinew/model/model_spec.h>

#include <string>

namespace sinew::cli {

/// The row of an initial-states table a run starts from.
struct InitialStates {
  std::string path;   ///< the file read
  io::Storage table;  ///< its rows, angles in radians
  int row = 0;        ///< the row used
  double time() const { return table.time[row]; }
};

/// Reads the initial-states table `path` for `spec` (ReadTableFor) and applies its first row
/// (ApplyInitialStates below).
InitialStates ApplyInitialStates(const std::string& path, bool strict, model::ModelSpec& spec);

/// Applies row `states.row` of a table read and checked for `spec`: its coordinate values and
/// speeds (OpenSim 4 paths or old names; rotational columns converted when the file is in
/// degrees) become the coordinates' default values and speeds in `spec`, so locked coordinates
/// are held at the file's value. Columns that name no simulated coordinate nor a state variable
/// of a simulated force are reported in one warning line, an error with `strict`; simulated
/// coordinates the file does not name keep their defaults, with one warning line (OpenSim warns
/// and uses the defaults too).
void ApplyInitialStates(InitialStates& states, bool strict, model::ModelSpec& spec);

/// Sets the auxiliary state variables of `state` that the row names (`/forceset/<element>/<var>`
/// or the OpenSim 3 `<element>.<var>`), with one warning line for the state variables it does
/// not name (they keep their defaults).
void ApplyInitialStateVariables(const InitialStates& states, const engine::System& system,
                                engine::State& state);

}  // namespace sinew::cli

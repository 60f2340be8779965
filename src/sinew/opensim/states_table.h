// The states table of a simulation in OpenSim 4's layout: one column per coordinate value and
// speed ("/jointset/<joint>/<coordinate>/value", ".../speed") and one per auxiliary state
// variable ("/forceset/<element>/<variable>", e.g. /forceset/soleus_r/activation).
#pragma once

#include <sinew/engine/state.h>
#include <sinew/engine/system.h>

#include <string>
#include <vector>

namespace sinew::opensim {

/// The column labels of `system`'s states, in StatesRow order.
std::vector<std::string> StatesLabels(const engine::System& system);

/// The values of `state` in StatesLabels order (radians, metres), written into `row` (resized).
void StatesRow(const engine::System& system, const engine::State& state, std::vector<double>& row);

/// The column labels of OpenSim's controls table (`<name>_controls.sto`): one column per input
/// of `system`, named after its element when the element has one input (an actuator's name, as
/// OpenSim names a ScalarActuator's control), else `<element>/<input>`.
std::vector<std::string> ControlsLabels(const engine::System& system);

/// The inputs of `state` in ControlsLabels order, written into `row` (resized).
void ControlsRow(const engine::State& state, std::vector<double>& row);

}  // namespace sinew::opensim

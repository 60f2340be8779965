// What every run of a model starts from, shared by Model.simulate, Model.simulator and Batch:
// the model (built again when an initial-states table or a controls file is given, as
// `sinew simulate` builds it), the initial state, and the controller of the excitations.
#pragma once

#include <pybind11/pybind11.h>
#include <sinew/engine/controller.h>
#include <sinew/engine/state.h>

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "model_handle.h"

namespace sinew::python {

namespace py = pybind11;

struct RunSetup {
  ModelPtr model;       ///< the model to run (`model`, or it built again)
  engine::State state;  ///< the initial state
  std::shared_ptr<const engine::Controller> controller;  ///< the excitations (may be null)
};

/// `initial_states`: None (the default state), a sinew.State, or the path of a states table
/// whose first row gives the coordinates (a warning lists the columns it could not use).
/// `excitations`: actuator name -> a number (constant), a sinew.Function, or a Python
/// callable f(t) -> float (called with the GIL at every evaluation: slower). `controls`: an
/// OpenSim ControlSet file. `equilibrate_muscles`: the muscles' fibers are then set to
/// equilibrium at the initial state (EquilibrateMusclesWarning). `read_states`: the table
/// already read from the `initial_states` path, or null to read it. Throws sinew::Error for bad
/// input.
RunSetup PrepareRun(const ModelPtr& model, const py::object& initial_states,
                    const std::optional<std::map<std::string, py::object>>& excitations,
                    const std::optional<std::filesystem::path>& controls,
                    bool equilibrate_muscles = false, const io::Storage* read_states = nullptr);

/// A Python UserWarning with `message` (raises when the warnings filter makes it an error).
void Warn(const std::string& message);

/// Sets every muscle of `model` in `state` to muscle-tendon equilibrium (OpenSim's
/// equilibrateMuscles); a muscle left unbalanced is a UserWarning naming it.
void EquilibrateMusclesWarning(const ModelHandle& model, engine::State& state);

}  // namespace sinew::python

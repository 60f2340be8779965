#include "simulation_inputs.h"

#include <sinew/common/error.h>
#include <sinew/common/text.h>
#include <sinew/engine/assemble.h>
#include <sinew/functions/constant.h>
#include <sinew/functions/excitations.h>
#include <sinew/muscles/equilibrate_muscles.h>
#include <sinew/opensim/initial_states.h>

#include <vector>

#include "state_handle.h"

namespace sinew::python {
namespace {

functions::FunctionPtr ToFunction(const std::string& actuator, const py::object& value) {
  if (py::isinstance<functions::Function>(value)) {
    return value.cast<std::shared_ptr<functions::Function>>();
  }
  if (py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value)) {
    return std::make_shared<functions::Constant>(value.cast<double>());
  }
  if (PyCallable_Check(value.ptr())) {
    // A Python function of time, called with the GIL taken (the engine runs without it); the
    // object is released with the GIL held, whichever thread drops the last reference.
    std::shared_ptr<py::object> callable(new py::object(value), [](py::object* object) {
      py::gil_scoped_acquire gil;
      delete object;
    });
    return std::make_shared<functions::CallableFunction>(
        [callable](double t) {
          py::gil_scoped_acquire gil;
          return (*callable)(t).cast<double>();
        },
        "PythonFunction");
  }
  throw Error({}, actuator,
              "an excitation must be a number, a sinew.Function (Constant, Ramp, Sine) or a "
              "Python function of time, not " +
                  py::repr(value).cast<std::string>());
}

// Warns (Python's warnings) about what the reader of `file` read leniently, and about its
// columns that name nothing simulated.
void WarnAboutTable(const Diagnostics& notes, const std::vector<std::string>& labels,
                    const std::string& file) {
  for (const Diagnostic& note : notes) Warn(note.Format());
  if (labels.empty()) return;
  Warn(file + ": " + std::to_string(labels.size()) +
       " column(s) name no coordinate value or speed or state variable that is simulated: " +
       FirstFew(labels));
}

}  // namespace

void Warn(const std::string& message) {
  if (PyErr_WarnEx(PyExc_UserWarning, message.c_str(), 2) != 0) throw py::error_already_set();
}

void EquilibrateMusclesWarning(const ModelHandle& model, engine::State& state) {
  for (const muscles::UnbalancedMuscle& muscle :
       muscles::EquilibrateMuscles(model.system(), state)) {
    Warn(muscles::DescribeUnbalancedMuscle(muscle));
  }
}

RunSetup PrepareRun(const ModelPtr& model, const py::object& initial_states,
                    const std::optional<std::map<std::string, py::object>>& excitations,
                    const std::optional<std::filesystem::path>& controls, bool equilibrate_muscles,
                    const io::Storage* read_states) {
  RunSetup setup{model, {}, nullptr};
  const bool is_state = py::isinstance<StateHandle>(initial_states);
  std::string states_file;
  if (!initial_states.is_none() && !is_state) {
    states_file = py::str(py::module_::import("os").attr("fspath")(initial_states));
  }
  InitialStatesTable states;
  if (!states_file.empty() || controls) {
    setup.model =
        model->Rebuild(states_file, controls ? controls->string() : "", states, read_states);
    WarnAboutTable(states.warnings, states.unused_labels, states_file);
  }
  if (is_state) {
    setup.state = initial_states.cast<const StateHandle&>().state;
    engine::CheckState(setup.model->system(), setup.state);
  } else {
    setup.state = setup.model->DefaultState();
  }
  if (!states_file.empty()) {
    // The row's state variables (muscle activations, fiber lengths), as `sinew simulate
    // --initial-states` takes them; then, when asked, equilibrium at those activations.
    const std::vector<std::string> missing = opensim::ApplyInitialStateVariables(
        states.table, states.row, states_file, setup.model->system(), setup.state);
    if (!missing.empty()) {
      Warn(states_file + ": " + std::to_string(missing.size()) +
           " state variables are not in the file (" + FirstFew(missing) +
           "): they keep their defaults");
    }
  }
  if (equilibrate_muscles) EquilibrateMusclesWarning(*setup.model, setup.state);
  setup.controller = setup.model->parser().GetController();
  if (excitations && !excitations->empty()) {
    opensim::OpenSimParser parser = setup.model->parser();  // the model's stays as it is
    for (const auto& [name, value] : *excitations) {
      parser.SetExcitationFunction(name, ToFunction(name, value));
    }
    setup.controller = parser.GetController();
  }
  return setup;
}

}  // namespace sinew::python

// Model.simulator and sinew.Simulator: one copy of the model stepped by fixed intervals from
// Python, for control loops. step(controls) sets the actuators' inputs and returns the
// observation [q, u] as one new array: nothing else is allocated per call, and the GIL is kept
// (a step of a small model is shorter than releasing and taking it again). Its statistics are
// Result.statistics' since the last reset; NSC steps above the solver's tolerance are reported
// (ReportNewUnconvergedSteps) by the step() call in which they first happen.
#include <pybind11/stl.h>

#include <cstring>
#include <optional>
#include <span>

#include "arrays.h"
#include "bindings.h"
#include "run_statistics.h"
#include "simulation_inputs.h"
#include "state_handle.h"
#include "stepped_copy.h"

namespace sinew::python {
namespace {

class Simulator {
 public:
  Simulator(const RunSetup& setup, double step, const std::string& integrator, double accuracy)
      : model_(setup.model),
        initial_(setup.state),
        copy_(model_->system(), model_->parser(), integrator, Settings(step, accuracy), step) {
    copy_.Reset(initial_);
  }

  static engine::IntegratorSettings Settings(double step, double accuracy) {
    engine::IntegratorSettings settings;
    settings.step = step;
    settings.accuracy = accuracy;
    return settings;
  }

  py::array_t<double> Reset(const std::optional<StateHandle>& state) {
    copy_.Reset(state ? state->state : initial_);
    return Observation();
  }

  py::array_t<double> Step(const std::optional<DoubleArray>& controls, int repeat) {
    const engine::State& s = copy_.state();
    if (controls && (controls->ndim() != 1 || controls->shape(0) != s.inputs.size())) {
      throw Error("controls must be a 1-D array of " + std::to_string(s.inputs.size()) +
                  " values (one per actuator)");
    }
    if (repeat < 1) throw Error("repeat must be >= 1, not " + std::to_string(repeat));
    for (int k = 0; k < repeat; ++k) copy_.Step(controls ? controls->data() : nullptr);
    ReportNewUnconvergedSteps(*model_, std::span(&copy_, 1), "Simulator", false);
    return Observation();
  }

  // [q, u] in one new array.
  py::array_t<double> Observation() const {
    const engine::State& s = copy_.state();
    const auto n = s.q.size();
    py::array_t<double> out(2 * n);
    double* data = out.mutable_data();
    if (n > 0) {
      std::memcpy(data, s.q.data(), sizeof(double) * n);
      std::memcpy(data + n, s.u.data(), sizeof(double) * n);
    }
    return out;
  }

  const ModelPtr& model() const { return model_; }
  const engine::State& state() const { return copy_.state(); }
  py::dict Statistics() const { return RunStatistics(copy_.integrator()); }

 private:
  ModelPtr model_;
  engine::State initial_;
  SteppedCopy copy_;
};

}  // namespace

void BindSimulator(py::module_& m) {
  py::class_<Simulator>(m, "Simulator",
                        "One copy of a model stepped by fixed intervals (Model.simulator makes "
                        "one). The inputs are the controls given to step; the model's own "
                        "controllers are not used.")
      .def("reset", &Simulator::Reset, py::arg("state") = py::none(),
           "Starts again from `state` (default: the initial state); returns the observation.")
      .def("step", &Simulator::Step, py::arg("controls") = py::none(), py::arg("repeat") = 1,
           "Sets the actuators' inputs to `controls` (one per actuator; omitted: unchanged) and "
           "advances `repeat` steps (default 1) with them; returns the observation [q, u] (a "
           "new array of 2 x coordinates). NSC steps that stop above the solver's tolerance "
           "give a UserWarning at the call in which the first happens since the reset; with "
           "strict=True, sinew.Error at every call that adds one (after its steps).")
      .def_property_readonly("t", [](const Simulator& s) { return s.state().t; })
      .def_property_readonly("q", [](const Simulator& s) { return ToArray(s.state().q); })
      .def_property_readonly("u", [](const Simulator& s) { return ToArray(s.state().u); })
      .def_property_readonly(
          "state",
          [](const Simulator& s) {
            return StateHandle{s.model(), s.state()};
          },
          "A copy of the current state.")
      .def_property_readonly("model", &Simulator::model)
      .def_property_readonly(
          "statistics", &Simulator::Statistics,
          "What the steps since the last reset (or since it was made) did, with the keys and "
          "meanings of Result.statistics: the integrator's steps, rejected, evaluations; for "
          "NSC also nsc_solves, nsc_unconverged_steps, nsc_most_iterations, nsc_worst_residual "
          "(a new dict).");

  py::class_<ModelHandle, ModelPtr> model =
      py::reinterpret_borrow<py::class_<ModelHandle, ModelPtr>>(m.attr("Model"));
  model.def(
      "simulator",
      [](const ModelPtr& h, double step, const std::string& integrator, double accuracy,
         const py::object& initial_states, bool equilibrate_muscles) {
        return Simulator(
            PrepareRun(h, initial_states, std::nullopt, std::nullopt, equilibrate_muscles), step,
            integrator, accuracy);
      },
      py::arg("step"), py::kw_only(), py::arg("integrator") = "euler", py::arg("accuracy") = 1e-6,
      py::arg("initial_states") = py::none(), py::arg("equilibrate_muscles") = false,
      "A Simulator stepping this model by `step` seconds per call.");
}

}  // namespace sinew::python

// sinew.Batch: n independent copies of one model stepped together by fixed intervals, across a
// pool of threads with the GIL released. The System is shared read-only by all copies; each
// copy has its own State, integrator and inputs (a finalized System never changes, so threads
// may share it: ForceInterfaceTest.TwoThreadsShareOneSystemWithDifferentInputs). Its statistics
// are a Simulator's per copy, as arrays [n] by key (as t is); NSC steps above the solver's
// tolerance are reported (ReportNewUnconvergedSteps) after the step() in which they first happen.
#include <pybind11/stl.h>

#include <algorithm>
#include <cstring>
#include <optional>
#include <thread>
#include <vector>

#include "arrays.h"
#include "bindings.h"
#include "run_statistics.h"
#include "simulation_inputs.h"
#include "state_handle.h"
#include "stepped_copy.h"
#include "worker_pool.h"

namespace sinew::python {
namespace {

class Batch {
 public:
  Batch(const ModelPtr& model, int n, double step, const std::string& integrator,
        std::optional<int> threads, double accuracy)
      : model_(model), initial_(model->DefaultState()) {
    if (n < 1) throw Error("a Batch needs n >= 1 copies, not " + std::to_string(n));
    const int hardware = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    const int count = threads.value_or(hardware);
    if (count < 1) throw Error("threads must be >= 1, not " + std::to_string(count));
    engine::IntegratorSettings settings;
    settings.step = step;
    settings.accuracy = accuracy;
    copies_.reserve(n);
    for (int i = 0; i < n; ++i)
      copies_.emplace_back(model_->system(), model_->parser(), integrator, settings, step);
    pool_ = std::make_unique<WorkerPool>(std::min(count, n));
    for (SteppedCopy& copy : copies_) copy.Reset(initial_);
  }

  // None: every copy from the default state; a State: every copy from it; a sequence of n
  // States: copy i from states[i].
  void Reset(const py::object& states) {
    if (states.is_none()) {
      for (SteppedCopy& copy : copies_) copy.Reset(initial_);
    } else if (py::isinstance<StateHandle>(states)) {
      const engine::State& state = states.cast<const StateHandle&>().state;
      for (SteppedCopy& copy : copies_) copy.Reset(state);
    } else {
      const auto list = states.cast<std::vector<const StateHandle*>>();
      if (list.size() != copies_.size()) {
        throw Error("reset needs one State per copy: " + std::to_string(copies_.size()) + ", not " +
                    std::to_string(list.size()));
      }
      for (size_t i = 0; i < list.size(); ++i) copies_[i].Reset(list[i]->state);
    }
  }

  void Step(const std::optional<DoubleArray>& controls) {
    const auto n = static_cast<py::ssize_t>(copies_.size());
    const auto inputs = static_cast<py::ssize_t>(model_->system().num_inputs());
    const double* data = nullptr;
    if (controls) {
      if (controls->ndim() != 2 || controls->shape(0) != n || controls->shape(1) != inputs) {
        throw Error("controls must be an array of shape [" + std::to_string(n) + ", " +
                    std::to_string(inputs) + "] (copies x actuators)");
      }
      data = controls->data();
    } else if (inputs > 0) {
      throw Error("this model has " + std::to_string(inputs) +
                  " actuators: step needs controls of shape [n, actuators]");
    }
    {
      py::gil_scoped_release release;
      pool_->Run(static_cast<int>(n), [&](int i) {
        copies_[i].Step(data ? data + static_cast<size_t>(i) * inputs : nullptr);
      });
    }
    ReportNewUnconvergedSteps(*model_, copies_, "Batch", true);
  }

  // Every copy's RunStatistics, as one array [n] per key (int64 counts, float64 residuals).
  py::dict Statistics() const {
    std::vector<py::dict> per_copy;
    per_copy.reserve(copies_.size());
    for (const SteppedCopy& copy : copies_) per_copy.push_back(RunStatistics(copy.integrator()));
    const py::object array = py::module_::import("numpy").attr("array");
    py::dict out;
    for (const auto& [key, value] : per_copy.front()) {
      py::list column;
      for (const py::dict& statistics : per_copy) column.append(statistics[key]);
      out[key] = array(column);
    }
    return out;
  }

  // A [n, coordinates] array of q (speeds: false) or u (speeds: true).
  py::array_t<double> Coordinates(bool speeds) const {
    const size_t n = copies_.size(), nc = model_->system().num_coordinates();
    py::array_t<double> out({n, nc});
    double* data = out.mutable_data();
    for (size_t i = 0; i < n; ++i) {
      const VecX& v = speeds ? copies_[i].state().u : copies_[i].state().q;
      if (nc > 0) std::memcpy(data + i * nc, v.data(), sizeof(double) * nc);
    }
    return out;
  }

  py::array_t<double> Times() const {
    py::array_t<double> out(copies_.size());
    for (size_t i = 0; i < copies_.size(); ++i) out.mutable_data()[i] = copies_[i].state().t;
    return out;
  }

  StateHandle State(int i) const {
    if (i < 0 || i >= static_cast<int>(copies_.size())) throw py::index_error();
    return StateHandle{model_, copies_[i].state()};
  }

  int size() const { return static_cast<int>(copies_.size()); }
  int threads() const { return pool_->threads(); }
  const ModelPtr& model() const { return model_; }

 private:
  ModelPtr model_;
  engine::State initial_;
  std::vector<SteppedCopy> copies_;
  std::unique_ptr<WorkerPool> pool_;
};

}  // namespace

void BindBatch(py::module_& m) {
  py::class_<Batch>(m, "Batch",
                    "n independent copies of a model stepped together by fixed intervals, "
                    "across threads with the GIL released.")
      .def(py::init<const ModelPtr&, int, double, const std::string&, std::optional<int>, double>(),
           py::arg("model"), py::arg("n"), py::kw_only(), py::arg("step"),
           py::arg("integrator") = "euler", py::arg("threads") = py::none(),
           py::arg("accuracy") = 1e-6)
      .def("reset", &Batch::Reset, py::arg("states") = py::none(),
           "Starts every copy again: from the default state (None), from one State, or copy i "
           "from states[i].")
      .def("step", &Batch::Step, py::arg("controls") = py::none(),
           "Advances every copy by one step; controls is an [n, actuators] array (may be "
           "omitted for a model without actuators). NSC steps that stop above the solver's "
           "tolerance give one UserWarning, naming the copies, at the call in which a copy's "
           "first happens since the reset; with strict=True, sinew.Error at every call in "
           "which a copy adds one (after the step).")
      .def_property_readonly(
          "q", [](const Batch& b) { return b.Coordinates(false); },
          "Coordinate values, [n, coordinates] (a copy).")
      .def_property_readonly(
          "u", [](const Batch& b) { return b.Coordinates(true); },
          "Coordinate speeds, [n, coordinates] (a copy).")
      .def_property_readonly("t", &Batch::Times, "Times, [n] (a copy).")
      .def_property_readonly(
          "statistics", &Batch::Statistics,
          "Per copy, what its steps since the last reset did: a dict with the keys and "
          "meanings of Result.statistics (and Simulator.statistics), each an array [n] (a "
          "new dict).")
      .def("state", &Batch::State, py::arg("i"), "A copy of copy i's state.")
      .def_property_readonly("n", &Batch::size)
      .def_property_readonly("threads", &Batch::threads)
      .def_property_readonly("model", &Batch::model)
      .def("__len__", &Batch::size);
}

}  // namespace sinew::python

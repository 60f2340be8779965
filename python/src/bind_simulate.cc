// Model.simulate: engine::Simulate (the loop `sinew simulate` runs) over a model built as the
// CLI builds it, recording every reported state into NumPy arrays, with the contacts table
// (contacts.sto's columns: contact::ContactTableLabels, then an NSC run's
// contact::NscContactTable), and write_table, which writes a table with io::StorageWriter
// (states.sto byte for byte as the CLI writes it).
// Its statistics (RunStatistics) also say, for an NSC run, what its impulse solver did (a
// UserWarning when steps stopped above its tolerance).
// The GIL is released while the engine runs; Ctrl-C (KeyboardInterrupt) stops the run between
// steps through the driver's stop flag.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>
#include <sinew/common/text.h>
#include <sinew/contact/contact_table.h>
#include <sinew/contact/nsc_contact_table.h>
#include <sinew/engine/force_reporter.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/nsc_integrator.h>
#include <sinew/engine/simulation.h>
#include <sinew/functions/constant.h>
#include <sinew/io/storage.h>
#include <sinew/io/storage_writer.h>
#include <sinew/opensim/forward_run.h>
#include <sinew/opensim/initial_states.h>
#include <sinew/opensim/run_integrator.h>
#include <sinew/opensim/states_table.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <map>
#include <optional>

#include "arrays.h"
#include "bindings.h"
#include "run_statistics.h"
#include "simulation_inputs.h"
#include "state_handle.h"

namespace sinew::python {
namespace {

// A rows x columns array copied from row-major `values`.
py::array_t<double> ToMatrix(const std::vector<double>& values, size_t rows, size_t columns) {
  py::array_t<double> array({rows, columns});
  if (!values.empty())
    std::memcpy(array.mutable_data(), values.data(), sizeof(double) * values.size());
  return array;
}

// Checks for Ctrl-C at most every 50 ms of wall time, taking the GIL only then; sets `stop`
// when Python has a pending KeyboardInterrupt (or another signal handler raised).
class SignalCheck {
 public:
  explicit SignalCheck(std::atomic<bool>& stop) : stop_(stop) {}
  void operator()(double /*fraction*/, double /*t*/) {
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < std::chrono::milliseconds(50)) return;
    last_ = now;
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) stop_ = true;
  }

 private:
  std::atomic<bool>& stop_;
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

// One run from `setup` with `settings`: what Model.simulate and sinew.forward return.
py::object RunSimulation(const RunSetup& setup, double duration, const std::string& integrator_name,
                         const engine::IntegratorSettings& settings, double report_interval) {
  const engine::System& system = setup.model->system();
  engine::State state = setup.state;
  const auto integrator =
      opensim::MakeRunIntegrator(integrator_name, system, setup.model->parser(), settings);
  integrator->SetController(setup.controller);

  // The contacts table, as `sinew simulate` writes contacts.sto: the contact force elements'
  // columns, then (NSC) the stepper's contact impulses per step length.
  std::optional<contact::NscContactTable> nsc_table;
  if (const auto* nsc = dynamic_cast<const engine::NscIntegrator*>(integrator.get())) {
    if (const auto* provider =
            dynamic_cast<const contact::CollisionContactProvider*>(nsc->provider().get()))
      nsc_table.emplace(system, *nsc, *provider);
  }
  std::vector<std::string> contact_labels = contact::ContactTableLabels(system);
  if (nsc_table) {
    contact_labels.insert(contact_labels.end(), nsc_table->labels().begin(),
                          nsc_table->labels().end());
  }

  // forces.sto's and controls.sto's columns (OpenSim's ForceReporter and controls).
  const engine::ForceReporter force_reporter(system);
  const std::vector<std::string> control_labels = opensim::ControlsLabels(system);

  const size_t nc = system.num_coordinates(), nz = system.num_state_variables();
  std::vector<double> time, q, u, z, table, row, contacts, nsc_row, forces, controls;
  auto record = [&](const engine::State& s) {
    time.push_back(s.t);
    q.insert(q.end(), s.q.data(), s.q.data() + nc);
    u.insert(u.end(), s.u.data(), s.u.data() + nc);
    z.insert(z.end(), s.z.data(), s.z.data() + nz);
    opensim::StatesRow(system, s, row);
    table.insert(table.end(), row.begin(), row.end());
    force_reporter.CalcRow(s, row);
    forces.insert(forces.end(), row.begin(), row.end());
    opensim::ControlsRow(s, row);
    controls.insert(controls.end(), row.begin(), row.end());
    if (!contact_labels.empty()) {
      contact::ContactTableRow(system, s, row);
      contacts.insert(contacts.end(), row.begin(), row.end());
      if (nsc_table) {
        nsc_table->Row(nsc_row);
        contacts.insert(contacts.end(), nsc_row.begin(), nsc_row.end());
      }
    }
  };
  std::atomic<bool> stop = false;
  engine::SimulationOptions run;
  run.duration = duration;
  run.report_interval = report_interval;
  run.stop = &stop;
  run.progress = SignalCheck(stop);
  engine::SimulationResult result;
  {
    py::gil_scoped_release release;
    result = engine::Simulate(*integrator, state, run, record);
  }
  if (!result.completed) throw py::error_already_set();  // the KeyboardInterrupt

  const auto labels = opensim::StatesLabels(system);
  const size_t n = time.size();
  py::array_t<double> time_array(n);
  if (n > 0) std::memcpy(time_array.mutable_data(), time.data(), sizeof(double) * n);
  const py::dict statistics = RunStatistics(*integrator);
  // NSC steps above the solver's tolerance: a warning, as `sinew simulate` warns (strict: an
  // error, as `--strict`, which fails after writing its files; here there is no file, so the
  // run's result is not returned).
  if (UnconvergedSteps(*integrator) > 0) ReportUnconvergedSteps(*setup.model, *integrator, "");
  py::object result_type = py::module_::import("sinew.result").attr("Result");
  return result_type(py::arg("time") = time_array, py::arg("q") = ToMatrix(q, n, nc),
                     py::arg("u") = ToMatrix(u, n, nc), py::arg("z") = ToMatrix(z, n, nz),
                     py::arg("coordinates") = setup.model->CoordinateNames(),
                     py::arg("state_variables") = system.state_variable_names(),
                     py::arg("labels") = labels,
                     py::arg("states") = ToMatrix(table, n, labels.size()),
                     py::arg("final_state") = StateHandle{setup.model, state},
                     py::arg("statistics") = statistics, py::arg("contact_labels") = contact_labels,
                     py::arg("contacts") = ToMatrix(contacts, n, contact_labels.size()),
                     py::arg("force_labels") = force_reporter.labels(),
                     py::arg("forces") = ToMatrix(forces, n, force_reporter.labels().size()),
                     py::arg("control_labels") = control_labels,
                     py::arg("controls") = ToMatrix(controls, n, control_labels.size()));
}

py::object Simulate(const ModelPtr& model, double duration, double accuracy,
                    const std::string& integrator_name, std::optional<double> step,
                    double report_interval, const py::object& initial_states,
                    const std::optional<std::map<std::string, py::object>>& excitations,
                    const std::optional<std::filesystem::path>& controls,
                    bool equilibrate_muscles) {
  engine::IntegratorSettings settings;
  settings.accuracy = accuracy;
  settings.step = step.value_or(0.0);
  return RunSimulation(
      PrepareRun(model, initial_states, excitations, controls, equilibrate_muscles), duration,
      integrator_name, settings, report_interval);
}

// An OpenSim ForwardTool setup run as `sinew forward` runs it (its model with the setup's force
// set files, external loads, controls file and initial states, from initial_time, or the
// states table's row OpenSim takes for it, to final_time at the setup's tolerance and step
// bounds), returned as a Result instead of written.
py::object Forward(const std::filesystem::path& setup_file,
                   const std::optional<std::filesystem::path>& model_file,
                   const std::string& integrator_name, double report_interval,
                   bool equilibrate_muscles, const std::string& cylinder_refinement,
                   const std::map<std::string, std::string>& renamed_force_classes, bool strict) {
  opensim::ForwardRun run = opensim::PlanForwardRun(
      setup_file.string(), {.model_path = model_file ? model_file->string() : "",
                            .model_option = "model=",
                            .strict = strict,
                            .strict_option = "strict"});
  const io::ForwardSetup& setup = run.setup;
  for (const Diagnostic& note : run.notes) Warn(note.Format());
  for (const Diagnostic& warning : run.warnings) Warn(warning.Format());
  LoadOptions options;
  options.strict = strict;
  options.cylinder_refinement = cylinder_refinement;
  options.force_set_files = setup.force_set_files;
  options.replace_force_set = setup.replace_force_set;
  if (!setup.external_loads_file.empty())
    options.external_loads.push_back(setup.external_loads_file);
  for (const auto& renamed : renamed_force_classes)
    options.renamed_force_classes.push_back(renamed);
  options.start_time = setup.initial_time;
  const ModelPtr model = ModelHandle::Load(run.model_path, options);
  const py::object states =
      setup.states_file.empty() ? py::object(py::none()) : py::object(py::str(setup.states_file));
  const std::optional<std::filesystem::path> controls =
      setup.controls_file.empty() ? std::nullopt
                                  : std::optional<std::filesystem::path>(setup.controls_file);
  return RunSimulation(
      PrepareRun(model, states, std::nullopt, controls,
                 setup.solve_for_equilibrium_for_auxiliary_states || equilibrate_muscles,
                 run.states ? &*run.states : nullptr),
      run.duration(), integrator_name, run.integrator_settings(), report_interval);
}

// Writes a storage file with io::StorageWriter: header `name`, `labels`, then one row per time.
void WriteTable(const std::filesystem::path& path, const std::string& name,
                const std::vector<std::string>& labels, const DoubleArray& time,
                const DoubleArray& values) {
  if (time.ndim() != 1 || values.ndim() != 2 || values.shape(0) != time.shape(0) ||
      values.shape(1) != static_cast<py::ssize_t>(labels.size())) {
    throw Error({path.string(), 0}, "",
                "the table must have one row per time and one column per label");
  }
  io::Storage header;
  header.name = name;
  header.labels = labels;
  io::StorageWriter writer(path.string(), header);
  const size_t columns = labels.size();
  for (py::ssize_t i = 0; i < time.shape(0); ++i) {
    writer.AppendRow(time.data()[i], std::span<const double>(values.data() + i * columns, columns));
  }
  writer.Finish();
}

}  // namespace

void BindSimulate(py::module_& m) {
  py::class_<ModelHandle, ModelPtr> model =
      py::reinterpret_borrow<py::class_<ModelHandle, ModelPtr>>(m.attr("Model"));
  model.def("simulate", &Simulate, py::arg("duration"), py::kw_only(), py::arg("accuracy") = 1e-6,
            py::arg("integrator") = "rk45", py::arg("step") = py::none(),
            py::arg("report_interval") = 0.01, py::arg("initial_states") = py::none(),
            py::arg("excitations") = py::none(), py::arg("controls") = py::none(),
            py::arg("equilibrate_muscles") = false,
            "Forward simulation over `duration` seconds (what `sinew simulate` runs); returns "
            "a sinew.Result.");
  m.def("forward", &Forward, py::arg("setup"), py::kw_only(), py::arg("model") = py::none(),
        py::arg("integrator") = "rk45", py::arg("report_interval") = 0.01,
        py::arg("equilibrate_muscles") = false, py::arg("cylinder_refinement") = "several-wraps",
        py::arg("rename_force_classes") = std::map<std::string, std::string>{},
        py::arg("strict") = false,
        "Runs an OpenSim ForwardTool setup file (*_Setup_Forward.xml) as `sinew forward` "
        "does and returns a sinew.Result (its states are <name>_states.sto's).");
  m.def("write_table", &WriteTable, py::arg("path"), py::arg("name"), py::arg("labels"),
        py::arg("time"), py::arg("values"),
        "Writes an OpenSim storage file (.sto) as `sinew simulate` writes its tables.");
}

}  // namespace sinew::python

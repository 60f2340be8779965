#include "sinew/opensim/forward_run.h"

#include <sinew/common/text.h>
#include <sinew/opensim/initial_states.h>

namespace sinew::opensim {
namespace {

// OpenSim moves the initial time to the row it takes; the user is told when that happens.
std::optional<Diagnostic> StartRowNote(const ForwardRun& run) {
  if (run.start_time == run.setup.initial_time) return std::nullopt;
  const double initial_time = run.setup.initial_time;
  Diagnostic note;
  note.where = {run.setup.states_file, 0};
  note.message = (initial_time < run.states->time[0]
                      ? "the initial time " + FormatNumber(initial_time) + " precedes the first row"
                      : "no row at the initial time " + FormatNumber(initial_time)) +
                 "; the run starts at " + FormatNumber(run.start_time) +
                 " s, the time of the row used, as OpenSim's Forward tool does";
  return note;
}

}  // namespace

engine::IntegratorSettings ForwardRun::integrator_settings() const {
  engine::IntegratorSettings settings;
  settings.accuracy = setup.integrator_error_tolerance;
  settings.step = setup.maximum_integrator_step_size;
  settings.min_step = setup.minimum_integrator_step_size;
  return settings;
}

ForwardRun PlanForwardRun(const std::string& setup_file, const ForwardRunOptions& options) {
  ForwardRun run;
  run.setup = io::ReadForwardSetup(setup_file);
  const io::ForwardSetup& setup = run.setup;
  run.notes = setup.notes;
  for (const Diagnostic& warning : setup.warnings) {
    if (options.strict) {
      throw Error(warning.where, warning.component,
                  warning.message + " (" + options.strict_option + ")");
    }
    run.warnings.push_back(warning);
  }
  run.model_path = options.model_path.empty() ? setup.model_file : options.model_path;
  if (run.model_path.empty()) {
    throw Error(
        {setup.file, 0}, "/" + setup.name,
        "the setup names no model (<model_file> is empty): give one with " + options.model_option);
  }
  run.start_time = setup.initial_time;
  if (!setup.states_file.empty()) {
    run.states = io::ReadStorage(setup.states_file);
    if (run.states->NumRows() == 0) {
      throw Error({setup.states_file, 0}, "", "the initial-states file has no rows");
    }
    run.start_row = ForwardStartRow(*run.states, setup.initial_time);
    run.start_time = run.states->time[run.start_row];
    if (auto note = StartRowNote(run)) run.notes.push_back(*note);
  }
  if (!(setup.final_time > run.start_time)) {
    throw Error({setup.file, 0}, "/" + setup.name,
                "the run would start at " + FormatNumber(run.start_time) +
                    " s (the states file's row), not before final_time " +
                    FormatNumber(setup.final_time));
  }
  return run;
}

}  // namespace sinew::opensim

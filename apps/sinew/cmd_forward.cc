// `sinew forward SETUP.xml [--model F.osim] [--out DIR] [--report-interval DT] [--strict]
//  [--equilibrate-muscles] [--rename-force-class OLD=NEW] [--cylinder-refinement RULE]
//  [--integrator rk45|cvode|cvode-gmres|cvode-gmres-bd] [--disable-force NAME]... [--quiet]`:
//  runs an OpenSim ForwardTool setup file (io::ReadForwardSetup; docs/forward.md):
// the model with the setup's force set files, initial states, controls and external loads,
// integrated from initial_time to final_time at the setup's accuracy. Writes <name>_states.sto,
// <name>_states_degrees.mot, <name>_controls.sto and <name>_forces.sto in OpenSim's layout into
// the setup's results_directory (or --out), streamed as rows are computed, with `simulate`'s
// progress bar and clean stop on SIGINT/SIGTERM.
#include <sinew/common/error.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/integrator.h>
#include <sinew/io/forward_setup.h>
#include <sinew/io/osim_reader.h>
#include <sinew/opensim/forward_run.h>

#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "apps/sinew/commands.h"
#include "apps/sinew/initial_states.h"
#include "apps/sinew/notices.h"
#include "apps/sinew/option_checks.h"
#include "apps/sinew/output_files.h"
#include "apps/sinew/run_simulation.h"
#include "apps/sinew/tables.h"

namespace sinew::cli {
namespace {

struct ForwardOptions {
  std::string setup;
  std::string model;
  std::string out;
  double report_interval = 0.01;
  bool strict = false;
  bool quiet = false;
  bool equilibrate_muscles = false;
  std::vector<std::string> renamed_classes;
  std::vector<std::string> disabled_forces;
  std::string cylinder_refinement = "several-wraps";
  std::string integrator = "rk45";
};

void RunForward(const ForwardOptions& options) {
  opensim::ForwardRun run = opensim::PlanForwardRun(
      options.setup, {.model_path = options.model, .strict = options.strict});
  const io::ForwardSetup& setup = run.setup;
  for (const Diagnostic& note : run.notes) std::cerr << "sinew: note: " << note.Format() << "\n";
  for (const Diagnostic& warning : run.warnings) {
    std::cerr << "sinew: warning: " << warning.Format() << "\n";
  }
  const std::string& model_path = run.model_path;
  const std::string out = options.out.empty() ? setup.results_directory : options.out;
  PrepareOutputFolder(out, options.out.empty() ? "<results_directory>" : "--out");

  model::ModelSpec spec =
      io::ReadOsim(model_path, io::ForceSetFiles{setup.force_set_files, setup.replace_force_set});
  std::optional<InitialStates> initial;
  if (run.states) {
    initial = InitialStates{setup.states_file, std::move(*run.states), run.start_row};
    for (const Diagnostic& note : initial->table.notes) {
      std::cerr << "sinew: note: " << note.Format() << "\n";
    }
    CheckTable(initial->table, initial->path, spec);
    ApplyInitialStates(*initial, options.strict, spec);
  }
  const double t0 = run.start_time;
  const double duration = run.duration();
  CheckSimulationSize(duration, options.report_interval, 0.0);

  ModelOptions model_options;
  model_options.model_path = model_path;
  model_options.strict = options.strict;
  model_options.quiet = options.quiet;
  model_options.controls = setup.controls_file;
  if (!setup.external_loads_file.empty()) {
    model_options.external_loads.push_back(setup.external_loads_file);
  }
  model_options.equilibrate_muscles =
      setup.solve_for_equilibrium_for_auxiliary_states || options.equilibrate_muscles;
  model_options.renamed_force_classes = options.renamed_classes;
  model_options.disabled_forces = options.disabled_forces;
  model_options.cylinder_refinement = CylinderRefinementOption(options.cylinder_refinement);
  BuiltModel built = BuildModel(spec, model_options);
  const engine::System& system = *built.system;
  // As OpenSim: the states file's values first, then equilibrium of the auxiliary states.
  engine::State state = MakeStartState(system, initial ? &*initial : nullptr,
                                       model_options.equilibrate_muscles, t0, model_path);

  const auto integrator =
      engine::MakeIntegrator(options.integrator, system, run.integrator_settings());
  integrator->SetController(built.parser.GetController());

  const std::string base = out + "/" + setup.name;
  TableFiles files;
  files.states = base + "_states.sto";
  files.states_degrees = base + "_states_degrees.mot";
  files.controls = base + "_controls.sto";
  files.forces = base + "_forces.sto";
  RunTables tables(system, spec, files);
  RunWithProgress(*integrator, state, duration, options.report_interval, options.quiet, tables,
                  out);
  if (!options.quiet) {
    const auto& stats = integrator->stats();
    std::cout << "simulated " << ShowNumber(t0) << " to " << ShowNumber(setup.final_time)
              << " s of " << spec.name << ": " << DescribeSteps(stats) << "; wrote " << base
              << "_states.sto, _states_degrees.mot, _controls.sto and _forces.sto\n";
  }
}

}  // namespace

void AddForwardCommand(CLI::App& app) {
  auto options = std::make_shared<ForwardOptions>();
  CLI::App* cmd =
      app.add_subcommand("forward", "Run an OpenSim Forward tool setup file (*_Setup_Forward.xml)");
  cmd->add_option("setup", options->setup, "The ForwardTool setup file")->required();
  cmd->add_option("--model", options->model,
                  "The .osim file (instead of the setup's model_file, e.g. when it is empty)");
  cmd->add_option("--out", options->out, "Output folder (default: the setup's results_directory)");
  cmd->add_option("--report-interval", options->report_interval,
                  "Time between output rows (s, default 0.01)")
      ->check(FiniteNumber(0.0, true));
  cmd->add_flag("--strict", options->strict,
                "Fail (exit code 2) if anything in the setup, the model or the states file is "
                "approximated, not simulated or not used");
  AddMuscleOptions(cmd, options->equilibrate_muscles, options->renamed_classes,
                   options->cylinder_refinement);
  cmd->add_option(
      "--integrator", options->integrator,
      "rk45 (explicit, default), cvode, cvode-gmres or cvode-gmres-bd (implicit BDF for stiff "
      "muscles; see `simulate`), at the setup's error tolerance and step bounds");
  cmd->add_option("--disable-force", options->disabled_forces,
                  "Leave out the force of this name (model, force set files or external loads; "
                  "repeatable)");
  cmd->add_flag("--quiet", options->quiet,
                "No progress bar or summary (warnings are still printed)");
  cmd->callback([options]() { RunForward(*options); });
}

}  // namespace sinew::cli

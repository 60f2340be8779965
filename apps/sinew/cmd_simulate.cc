// `sinew simulate MODEL.osim --duration T [--accuracy A] [--integrator NAME] [--step H]
//  [--report-interval DT] [--initial-states FILE.sto] [--activate-actuators]
//  [--excitation NAME=KIND:ARGS]... [--controls FILE] [--external-loads FILE.xml]...
//  [--disable-force NAME]... [--strict] [--export FILE] [--verbose] [--quiet]
//  [--report-constraint-forces] --out DIR`: a forward simulation of what the OpenSim parser
// builds (skeleton, forces, constraints, external loads, actuators and their excitations).
// Writes DIR/states.sto (every coordinate's value and speed, OpenSim 4 labels, radians and
// metres), DIR/bodies.sto (OpenSim BodyKinematics positions), DIR/forces.sto (every force's
// columns, OpenSim's ForceReporter layout) and, when asked, DIR/constraints.sto (the forces of
// the model's constraints, OpenSim's record labels), all streamed as rows are computed. SIGINT
// or SIGTERM stops the run cleanly: the rows so far are kept, in files whose header says
// status=partial, and the exit code is 128 + the signal.
#include <sinew/common/error.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/force_reporter.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/pose.h>
#include <sinew/engine/simulation.h>
#include <sinew/io/osim_reader.h>
#include <sinew/io/storage.h>
#include <sinew/io/storage_labels.h>
#include <sinew/io/storage_writer.h>
#include <sinew/kinematics/body_kinematics.h>
#include <sinew/opensim/constraint_forces_table.h>
#include <sinew/opensim/parser.h>
#include <sinew/opensim/states_table.h>
#include <sinew/opensim/support.h>
#include <sinew/viz/export_animation.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "apps/sinew/commands.h"
#include "apps/sinew/excitation_option.h"
#include "apps/sinew/interrupt_guard.h"
#include "apps/sinew/notices.h"
#include "apps/sinew/option_checks.h"
#include "apps/sinew/output_files.h"
#include "apps/sinew/simulated_coordinates.h"
#include "apps/sinew/tables.h"

namespace sinew::cli {
namespace {

struct SimulateOptions {
  std::string model;
  double duration = 0.0;
  double accuracy = 1e-6;
  std::string integrator = "rk45";
  double step = 0.0;
  double report_interval = 0.01;
  std::string initial_states;
  std::string out;
  bool quiet = false;
  bool verbose = false;
  bool activate_actuators = false;
  std::vector<std::string> excitations;
  std::string controls;
  std::vector<std::string> external_loads;
  std::vector<std::string> disabled_forces;
  bool strict = false;
  std::string export_file;
  std::string vis = "mesh";
  std::vector<std::string> geometry_dirs;
  bool report_constraint_forces = false;
};

// Takes the first row of an initial-states file (OpenSim 4 paths or old names; rotational
// columns converted when the file is in degrees) as the coordinates' default values and speeds,
// so that locked coordinates are held at the file's value, as OpenSim's Forward tool does.
// Coordinates the file does not name keep their defaults; columns that name no simulated
// coordinate (muscle states, coordinates of stand-in joints) are reported in one line, an
// error with `strict`. Returns the row's time.
double ApplyInitialStates(const std::string& path, bool strict, model::ModelSpec& spec) {
  io::Storage storage = ReadTableFor(path, spec);
  if (storage.NumRows() == 0) throw Error({path, 0}, "", "the initial-states file has no rows");
  std::vector<std::string> rotational, simulated;
  for (const model::CoordinateSpec& c : spec.coordinates) {
    if (c.joint == model::kNone || !opensim::IsJointSimulated(spec.joints[c.joint])) continue;
    simulated.push_back(c.name);
    if (c.motion_type == model::MotionType::kRotational) rotational.push_back(c.name);
  }
  std::vector<std::string> unused;
  for (const std::string& label : storage.labels) {
    if (!io::ParseColumnLabel(label, simulated)) unused.push_back(label);
  }
  WarnUnusedColumns(unused, path, "they name no coordinate value or speed that is simulated",
                    strict);
  io::ConvertDegreesToRadians(storage, rotational);
  for (model::CoordinateSpec& c : spec.coordinates) {
    const int value = io::FindCoordinateColumn(storage, c.name, io::CoordinateColumnKind::kValue);
    const int speed = io::FindCoordinateColumn(storage, c.name, io::CoordinateColumnKind::kSpeed);
    if (value >= 0) c.default_value = storage.Value(0, value);
    if (speed >= 0) c.default_speed_value = storage.Value(0, speed);
  }
  return storage.time[0];
}

void ShowProgress(double fraction, double t) {
  const int width = 40;
  const int filled = static_cast<int>(fraction * width);
  std::fprintf(stderr, "\r[%s%s] %3d%%  t = %.3f s", std::string(filled, '#').c_str(),
               std::string(width - filled, ' ').c_str(), static_cast<int>(100 * fraction), t);
  std::fflush(stderr);
}

void RunSimulate(const SimulateOptions& options) {
  // Before any work: a run of absurd size, or outputs that cannot be written, is a usage error.
  CheckSimulationSize(options.duration, options.report_interval, options.step);
  PrepareOutputFolder(options.out);
  if (!options.export_file.empty()) {
    viz::ExportFormatOf(options.export_file);
    PrepareOutputFile(options.export_file, "--export");
  }
  model::ModelSpec spec = io::ReadOsim(options.model);
  double t0 = 0.0;
  if (!options.initial_states.empty()) {
    t0 = ApplyInitialStates(options.initial_states, options.strict, spec);
  }
  WarnNotSimulated(spec, options.model, options.strict, options.disabled_forces);
  opensim::OpenSimParser parser;
  parser.ActivateActuators(options.activate_actuators);
  parser.SetControlsFile(options.controls);
  parser.SetStrict(options.strict);
  for (const std::string& file : options.external_loads) parser.AddExternalLoads(file);
  for (const std::string& name : options.disabled_forces) parser.DisableForce(name);
  auto system = std::make_unique<engine::System>();
  parser.ParseSpec(*system, spec);
  system->Finalize();
  for (const std::string& option : options.excitations) {
    auto [name, function] = ParseExcitationOption(option);
    parser.SetExcitationFunction(name, std::move(function));
  }
  const opensim::Report& report = parser.GetReport();
  if (!options.quiet && !report.warnings().empty()) {
    std::cerr << "sinew: note: " << report.warnings().size()
              << " warning(s) from reading and building the model; `sinew inspect " << options.model
              << "` lists them\n";
  }
  engine::State state;
  try {
    state = engine::MakeDefaultState(*system, t0);
  } catch (const Error& error) {  // e.g. constraints that cannot be assembled: name the model
    if (!error.where().file.empty()) throw;
    throw Error({options.model, 0}, error.component(), error.message());
  }
  engine::IntegratorSettings settings;
  settings.accuracy = options.accuracy;
  settings.step = options.step;
  const auto integrator = engine::MakeIntegrator(options.integrator, *system, settings);
  integrator->SetController(parser.GetController());

  // The tables are streamed to disk as the run computes them (bounded memory).
  io::Storage states_header, bodies_header, forces_header;
  states_header.name = "states";
  states_header.labels = opensim::StatesLabels(*system);
  // bodies.sto as `sinew kinematics` writes it (OpenSim BodyKinematics positions; the angles
  // are degrees, and the header says so).
  bodies_header.name = "Positions";
  bodies_header.labels = kinematics::BodyKinematicsLabels(spec);
  bodies_header.in_degrees = true;
  // forces.sto as OpenSim's ForceReporter writes it (forces with appliesForce false are left out).
  const engine::ForceReporter force_reporter(*system);
  forces_header.name = "ForceReporter";
  forces_header.labels = force_reporter.labels();
  io::StorageWriter states(options.out + "/states.sto", states_header);
  io::StorageWriter bodies(options.out + "/bodies.sto", bodies_header);
  io::StorageWriter forces(options.out + "/forces.sto", forces_header);
  std::vector<double> force_row;
  std::optional<io::StorageWriter> constraints;
  engine::Data data(*system);
  std::vector<double> constraint_row;
  if (options.report_constraint_forces) {
    io::Storage header;
    header.name = "ConstraintForces";
    header.labels = opensim::ConstraintForcesLabels(*system);
    constraints.emplace(options.out + "/constraints.sto", header);
  }
  // A fresh system holds the spec's bodies in spec order (stand-ins add none).
  std::vector<Transform> X_GB(system->num_bodies());
  std::vector<double> row;
  viz::BodyMotion motion;
  // The coordinates too, so that the export draws the muscle paths.
  std::optional<SimulatedCoordinates> coordinates;
  if (!options.export_file.empty()) coordinates.emplace(spec, *system, state);
  auto record = [&](const engine::State& s) {
    opensim::StatesRow(*system, s, row);
    states.AppendRow(s.t, row);
    for (int b = 0; b < system->num_bodies(); ++b) X_GB[b] = engine::PoseOf(s.bodies[b]);
    bodies.AppendRow(s.t, kinematics::CalcBodyKinematicsRow(spec, X_GB));
    force_reporter.CalcRow(s, force_row);
    forces.AppendRow(s.t, force_row);
    if (constraints) {
      // External loads are force elements of the system, so no loads are passed besides them.
      opensim::ConstraintForcesRow(*system, s, nullptr, data, constraint_row);
      constraints->AppendRow(s.t, constraint_row);
    }
    if (!options.export_file.empty()) {
      motion.times.push_back(s.t);
      motion.X_GB.push_back(X_GB);
      motion.q.push_back(coordinates->Read(s));
    }
  };

  engine::SimulationOptions run;
  run.duration = options.duration;
  run.report_interval = options.report_interval;
  const InterruptGuard interrupt;
  run.stop = &interrupt.flag();
  if (!options.quiet && isatty(fileno(stderr))) run.progress = ShowProgress;
  const engine::SimulationResult result = engine::Simulate(*integrator, state, run, record);
  if (run.progress) std::fprintf(stderr, "\n");
  std::string partial;
  if (!result.completed) {
    partial = "stopped by " + interrupt.SignalName() + " at t = " + std::to_string(state.t) + " s";
  }
  states.Finish(partial);
  bodies.Finish(partial);
  forces.Finish(partial);
  if (constraints) constraints->Finish(partial);
  if (!result.completed) {
    std::cerr << "sinew: " << partial << ": kept the " << states.rows() << " rows computed in "
              << options.out
              << "/states.sto, bodies.sto and forces.sto (their headers say status=partial)\n";
    throw ExitRequest{128 + interrupt.Signal()};
  }
  if (!options.export_file.empty()) {
    viz::ExportOptions export_options;
    export_options.visual.mode = viz::ParseVisType(options.vis);
    export_options.visual.geometry_dirs = options.geometry_dirs;
    PrintSceneWarnings(viz::ExportAnimation(spec, motion, options.export_file, export_options),
                       options.verbose);
  }
  if (!options.quiet) {
    const auto& stats = integrator->stats();
    std::cout << "simulated " << options.duration << " s of " << spec.name << ": " << stats.steps
              << " steps (" << stats.rejected << " rejected), " << stats.evaluations
              << " evaluations; wrote " << options.out << "/states.sto, bodies.sto, forces.sto"
              << (constraints ? " and constraints.sto\n" : "\n");
  }
}

}  // namespace

void AddSimulateCommand(CLI::App& app) {
  auto options = std::make_shared<SimulateOptions>();
  CLI::App* cmd = app.add_subcommand(
      "simulate", "Forward simulation of a model (skeleton, forces, actuators, external loads)");
  cmd->add_option("model", options->model, "The .osim file")->required();
  cmd->add_option("--duration", options->duration, "Simulated time (s)")
      ->required()
      ->check(FiniteNumber(0.0));
  cmd->add_option("--accuracy", options->accuracy, "Integrator accuracy (default 1e-6)")
      ->check(FiniteNumber(0.0, true));
  cmd->add_option("--integrator", options->integrator,
                  "rk45 (error-controlled, default), euler or implicit-euler (fixed step)");
  cmd->add_option("--step", options->step, "Fixed step for euler; largest step for rk45 (s)")
      ->check(FiniteNumber(0.0));
  cmd->add_option("--report-interval", options->report_interval,
                  "Time between output rows (s, default 0.01)")
      ->check(FiniteNumber(0.0, true));
  cmd->add_option("--initial-states", options->initial_states,
                  "Storage file whose first row gives the initial coordinates and speeds");
  cmd->add_option("--out", options->out, "Output folder")->required();
  cmd->add_flag("--activate-actuators", options->activate_actuators,
                "Excite every actuator with the constant 1");
  cmd->add_option("--excitation", options->excitations,
                  "NAME=constant:V | NAME=ramp:START,SLOPE | NAME=sine:AMPLITUDE,FREQUENCY_HZ,PHASE"
                  " (repeatable; overrides the other sources for that actuator)");
  cmd->add_option("--controls", options->controls,
                  "OpenSim ControlSet file (e.g. *_controls.xml) driving the actuators it names");
  cmd->add_option("--external-loads", options->external_loads,
                  "OpenSim ExternalLoads file (.xml; its datafile is read relative to it) whose "
                  "ExternalForces are applied (repeatable)");
  cmd->add_option("--disable-force", options->disabled_forces,
                  "Leave out the force of this name (model or external loads; repeatable)");
  cmd->add_flag("--strict", options->strict,
                "Fail (exit code 2) if anything in the model or the initial states is "
                "approximated, not simulated or not used");
  cmd->add_option("--export", options->export_file,
                  "Also write the motion as a .glb or self-contained .html viewer");
  cmd->add_option("--vis", options->vis, "Visualization for --export: mesh (default), primitives")
      ->check(CLI::IsMember({"primitives", "mesh"}));
  cmd->add_option("--geometry-dir", options->geometry_dirs,
                  "Extra folder to search for mesh files (repeatable)");
  cmd->add_flag("--verbose", options->verbose,
                "With --export: list every missing mesh file, not just how many");
  cmd->add_flag("--report-constraint-forces", options->report_constraint_forces,
                "Also write DIR/constraints.sto: the forces of the model's constraints");
  cmd->add_flag("--quiet", options->quiet,
                "No progress bar or summary (warnings are still printed)");
  cmd->callback([options]() { RunSimulate(*options); });
}

}  // namespace sinew::cli

// `sinew simulate MODEL.osim --duration T [--accuracy A] [--integrator NAME] [--step H]
//  [--report-interval DT] [--initial-states FILE.sto] [--activate-actuators]
//  [--excitation NAME=KIND:ARGS]... [--controls FILE] [--external-loads FILE.xml]...
//  [--disable-force NAME]... [--strict] [--export FILE] [--verbose] [--quiet]
//  [--report-constraint-forces] [--equilibrate-muscles] [--rename-force-class OLD=NEW]
//  [--cylinder-refinement several-wraps|opensim-4.4|always]
//  [--collision [--contact smc|nsc] [--ground-plane H] [material options] [--nsc-solver
//  apgd|gauss-seidel] [--nsc-iterations N] [--nsc-tolerance TOL] ...] --out DIR`: a forward
//  simulation of what the OpenSim parser
// builds (skeleton, forces, constraints, external loads, actuators and their excitations).
// Writes DIR/states.sto (every coordinate's value and speed, OpenSim 4 labels, radians and
// metres), DIR/bodies.sto (OpenSim BodyKinematics positions), DIR/forces.sto (every force's
// columns, OpenSim's ForceReporter layout), DIR/contacts.sto when the model has contact forces
// or collides with NSC (each one's force and torque per body and its active contacts) and, when
// asked, DIR/constraints.sto (the forces of the model's constraints, OpenSim's record labels),
// all streamed as rows are computed. SIGINT or SIGTERM stops the run cleanly: the rows so far are
// kept, in files whose header says status=partial, and the exit code is 128 + the signal.
#include <sinew/contact/collision_contact_provider.h>
#include <sinew/contact/contact_force.h>
#include <sinew/contact/nsc_contact_table.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/nsc_integrator.h>
#include <sinew/engine/pose.h>
#include <sinew/io/osim_reader.h>
#include <sinew/io/storage.h>
#include <sinew/opensim/collision_parts.h>
#include <sinew/opensim/run_integrator.h>
#include <sinew/viz/export_animation.h>

#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "apps/sinew/commands.h"
#include "apps/sinew/contact_options.h"
#include "apps/sinew/initial_states.h"
#include "apps/sinew/interrupt_guard.h"
#include "apps/sinew/notices.h"
#include "apps/sinew/option_checks.h"
#include "apps/sinew/output_files.h"
#include "apps/sinew/run_simulation.h"
#include "apps/sinew/simulated_coordinates.h"

namespace sinew::cli {
namespace {

// The body of every column group "<force>.<group>" of the system's contact forces and of NSC's
// table, when there is one (engine body i is spec body i).
viz::GroupBodies ContactGroupBodies(const engine::System& system,
                                    const contact::NscContactTable* nsc) {
  viz::GroupBodies bodies;
  if (nsc) {
    for (const int b : nsc->bodies()) {
      bodies[std::string(contact::kNscTableName) + "." + system.bodies()[b].name] = b;
    }
  }
  for (const auto& element : system.force_elements()) {
    const auto* force = dynamic_cast<const contact::ContactForce*>(element.get());
    if (!force) continue;
    for (const contact::ContactForce::RecordGroup& g : force->record_groups()) {
      bodies[force->name() + "." + g.label] = g.body;
    }
  }
  return bodies;
}

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
  bool equilibrate_muscles = false;
  std::vector<std::string> renamed_classes;
  std::string cylinder_refinement = "several-wraps";
  ContactOptions contact;
};

void RunSimulate(const SimulateOptions& options) {
  // Before any work: a run of absurd size, or outputs that cannot be written, is a usage error.
  CheckSimulationSize(options.duration, options.report_interval, options.step);
  PrepareOutputFolder(options.out);
  if (!options.export_file.empty()) {
    viz::ExportFormatOf(options.export_file);
    PrepareOutputFile(options.export_file, "--export");
  }
  model::ModelSpec spec = io::ReadOsim(options.model);
  std::optional<InitialStates> initial;
  if (!options.initial_states.empty()) {
    initial = ApplyInitialStates(options.initial_states, options.strict, spec);
  }
  BuiltModel built = BuildModel(
      spec, {.model_path = options.model,
             .strict = options.strict,
             .quiet = options.quiet,
             .activate_actuators = options.activate_actuators,
             .controls = options.controls,
             .external_loads = options.external_loads,
             .disabled_forces = options.disabled_forces,
             .excitations = options.excitations,
             .equilibrate_muscles = options.equilibrate_muscles,
             .renamed_force_classes = options.renamed_classes,
             .cylinder_refinement = CylinderRefinementOption(options.cylinder_refinement),
             .contact = options.contact,
             .geometry_dirs = options.geometry_dirs});
  const engine::System& system = *built.system;
  engine::State state =
      MakeStartState(system, initial ? &*initial : nullptr, options.equilibrate_muscles,
                     initial ? initial->time() : 0.0, options.model);
  engine::IntegratorSettings settings;
  settings.accuracy = options.accuracy;
  settings.step = options.step;
  const auto integrator =
      opensim::MakeRunIntegrator(options.integrator, system, built.parser, settings);
  integrator->SetController(built.parser.GetController());

  TableFiles files;
  files.states = options.out + "/states.sto";
  files.bodies = options.out + "/bodies.sto";
  files.forces = options.out + "/forces.sto";
  if (options.report_constraint_forces) files.constraints = options.out + "/constraints.sto";
  files.contacts = options.out + "/contacts.sto";
  // NSC's collision contacts are the stepper's impulses, not a force element's: their columns
  // come from the stepper's last step.
  std::optional<contact::NscContactTable> nsc_table;
  if (const auto* nsc = dynamic_cast<const engine::NscIntegrator*>(integrator.get())) {
    if (const auto* provider =
            dynamic_cast<const contact::CollisionContactProvider*>(nsc->provider().get()))
      nsc_table.emplace(system, *nsc, *provider);
  }
  RunTables tables(system, spec, files, nsc_table ? &*nsc_table : nullptr);
  viz::BodyMotion motion;
  std::function<void(const engine::State&)> record_motion;
  // The coordinates too, so that the export draws the muscle paths.
  std::optional<SimulatedCoordinates> coordinates;
  if (!options.export_file.empty()) {
    coordinates.emplace(spec, system, state);
    record_motion = [&](const engine::State& s) {
      motion.times.push_back(s.t);
      motion.X_GB.emplace_back();
      for (const engine::BodyState& body : s.bodies)
        motion.X_GB.back().push_back(engine::PoseOf(body));
      motion.q.push_back(coordinates->Read(s));
    };
  }
  // What NSC's impulse solver did; loudly when steps stopped short of its tolerance (also for a
  // run stopped by a signal, over the steps it took, which keeps its exit code). With --strict
  // such steps fail the run once every file is written (below).
  const auto* nsc = dynamic_cast<const engine::NscIntegrator*>(integrator.get());
  try {
    RunWithProgress(*integrator, state, options.duration, options.report_interval, options.quiet,
                    tables, options.out, record_motion);
  } catch (const ExitRequest&) {
    if (nsc) ReportNscSolves(nsc->solve_summary(), nsc->nsc_settings(), options.quiet);
    throw;
  }
  if (nsc && !options.strict) {
    ReportNscSolves(nsc->solve_summary(), nsc->nsc_settings(), options.quiet);
  }
  if (!options.export_file.empty()) {
    viz::ExportOptions export_options;
    export_options.visual.mode = viz::ParseVisType(options.vis);
    export_options.visual.geometry_dirs = options.geometry_dirs;
    // With --collision the shapes that collide, in the contact colour.
    export_options.collision_parts = opensim::CollisionPartsOf(built.parser.GetCollisionModel());
    if (options.contact.collision && options.contact.ground_plane) {
      export_options.floor = viz::HorizontalFloor(*options.contact.ground_plane, "--ground-plane");
    }
    // The contact forces as arrows, from the contacts.sto just written.
    io::Storage contacts;
    if (tables.writes_contacts()) {
      contacts = io::ReadStorage(files.contacts);
      export_options.contacts = &contacts;
      export_options.contact_groups = ContactGroupBodies(system, nsc_table ? &*nsc_table : nullptr);
    }
    PrintSceneWarnings(viz::ExportAnimation(spec, motion, options.export_file, export_options),
                       options.verbose);
  }
  if (nsc && options.strict) {
    ReportNscSolves(nsc->solve_summary(), nsc->nsc_settings(), options.quiet, true);
  }
  if (!options.quiet) {
    const auto& stats = integrator->stats();
    std::cout << "simulated " << options.duration << " s of " << spec.name << ": "
              << DescribeSteps(stats) << "; wrote " << options.out
              << "/states.sto, bodies.sto, forces.sto"
              << (tables.writes_contacts() ? ", contacts.sto" : "")
              << (options.report_constraint_forces ? " and constraints.sto\n" : "\n");
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
  cmd->add_option(
      "--integrator", options->integrator,
      "rk45 (error-controlled, explicit, default), cvode (error-controlled, implicit BDF: "
      "stiff muscles, dense Jacobian: small models), cvode-gmres (the same, matrix-free: large "
      "models), cvode-gmres-bd (the same, preconditioned by the muscles' own activation and "
      "fiber Jacobians: fibers far from equilibrium), euler or implicit-euler (fixed step)");
  cmd->add_option("--step", options->step,
                  "Fixed step for euler; largest step for rk45 and cvode(-gmres) (s)")
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
  cmd->add_option(
      "--controls", options->controls,
      "OpenSim ControlSet file (*_controls.xml, or a .sto table) driving the actuators it names");
  cmd->add_option("--external-loads", options->external_loads,
                  "OpenSim ExternalLoads file (.xml; its datafile is read relative to it) whose "
                  "ExternalForces are applied (repeatable)");
  cmd->add_option("--disable-force", options->disabled_forces,
                  "Leave out the force of this name (model or external loads; repeatable)");
  cmd->add_flag("--strict", options->strict,
                "Fail (exit code 2) if anything in the model or the initial states is "
                "approximated, not simulated or not used, or (after writing the outputs) if "
                "NSC's impulse solver left a step above its tolerance");
  cmd->add_option("--export", options->export_file,
                  "Also write the motion as a .glb or self-contained .html viewer (with the "
                  "contact forces as arrows when contacts.sto is written)");
  cmd->add_option("--vis", options->vis, "Visualization for --export: mesh (default), primitives")
      ->check(CLI::IsMember({"primitives", "mesh"}));
  cmd->add_option("--geometry-dir", options->geometry_dirs,
                  "Extra folder to search for mesh files, visual and ContactMesh (repeatable)");
  cmd->add_flag("--verbose", options->verbose,
                "With --export: list every missing mesh file, not just how many");
  AddMuscleOptions(cmd, options->equilibrate_muscles, options->renamed_classes,
                   options->cylinder_refinement);
  AddContactOptions(cmd, options->contact);
  cmd->add_flag("--report-constraint-forces", options->report_constraint_forces,
                "Also write DIR/constraints.sto: the forces of the model's constraints");
  cmd->add_flag("--quiet", options->quiet,
                "No progress bar or summary (warnings are still printed)");
  cmd->callback([options]() { RunSimulate(*options); });
}

}  // namespace sinew::cli

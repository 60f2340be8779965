#include "apps/sinew/run_simulation.h"

#include <sinew/common/error.h>
#include <sinew/contact/contact_table.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/pose.h>
#include <sinew/kinematics/body_kinematics.h>
#include <sinew/muscles/equilibrate_muscles.h>
#include <sinew/opensim/collision_settings.h>
#include <sinew/opensim/constraint_forces_table.h>
#include <sinew/opensim/states_table.h>
#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <numbers>

#include "apps/sinew/excitation_option.h"
#include "apps/sinew/interrupt_guard.h"
#include "apps/sinew/notices.h"

namespace sinew::cli {
namespace {

void ShowProgress(double fraction, double t) {
  const int width = 40;
  const int filled = static_cast<int>(fraction * width);
  std::fprintf(stderr, "\r[%s%s] %3d%%  t = %.3f s", std::string(filled, '#').c_str(),
               std::string(width - filled, ' ').c_str(), static_cast<int>(100 * fraction), t);
  std::fflush(stderr);
}

// A writer for `file` with `name` and `labels` in its header, or none when `file` is empty.
void OpenTable(std::optional<io::StorageWriter>& writer, const std::string& file,
               const std::string& name, std::vector<std::string> labels, bool in_degrees = false) {
  if (file.empty()) return;
  io::Storage header;
  header.name = name;
  header.labels = std::move(labels);
  header.in_degrees = in_degrees;
  writer.emplace(file, header);
}

}  // namespace

BuiltModel BuildModel(const model::ModelSpec& spec, const ModelOptions& options) {
  // With --collision, the contact geometry that is a collision shape collides: it is simulated.
  model::ModelSpec shown;
  if (options.contact.collision) {
    shown = spec;
    std::erase_if(shown.contact_geometry, [](const model::ContactGeometrySpec& g) {
      return opensim::IsCollisionShapeClass(g.type);
    });
  }
  WarnNotSimulated(options.contact.collision ? shown : spec, options.model_path, options.strict,
                   options.disabled_forces);
  BuiltModel built;
  opensim::OpenSimParser& parser = built.parser;
  parser.ActivateActuators(options.activate_actuators);
  parser.SetControlsFile(options.controls);
  parser.SetStrict(options.strict);
  parser.EquilibrateMuscles(options.equilibrate_muscles);
  parser.SetCylinderRefinement(options.cylinder_refinement);
  for (const std::string& rename : options.renamed_force_classes) {
    const size_t eq = rename.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == rename.size()) {
      throw Error({}, "--rename-force-class", "expects OLD=NEW, got '" + rename + "'");
    }
    parser.RenameForceClass(rename.substr(0, eq), rename.substr(eq + 1));
  }
  for (const std::string& dir : options.geometry_dirs) parser.AddGeometryDir(dir);
  for (const std::string& file : options.external_loads) parser.AddExternalLoads(file);
  for (const std::string& name : options.disabled_forces) parser.DisableForce(name);
  ApplyContactOptions(options.contact, parser);
  built.system = std::make_unique<engine::System>();
  parser.ParseSpec(*built.system, spec);
  built.system->Finalize();
  for (const std::string& option : options.excitations) {
    auto [name, function] = ParseExcitationOption(option);
    parser.SetExcitationFunction(name, std::move(function));
  }
  const opensim::Report& report = parser.GetReport();
  if (!options.quiet && !report.warnings().empty()) {
    std::cerr << "sinew: note: " << report.warnings().size()
              << " warning(s) from reading and building the model; `sinew inspect "
              << options.model_path << "` lists them\n";
  }
  return built;
}

namespace {

// Equilibrates every muscle again (the same answer as at the start) to tell the user of each
// muscle whose equilibrium is not a balance of its forces (OpenSim warns of a fiber at its
// minimum length and keeps both kinds).
void WarnUnbalancedFibers(const engine::System& system, const engine::State& state) {
  engine::State copy = state;
  for (const muscles::UnbalancedMuscle& muscle : muscles::EquilibrateMuscles(system, copy)) {
    std::cerr << "sinew: warning: " << muscles::DescribeUnbalancedMuscle(muscle) << "\n";
  }
}

// One warning when muscles start with fiber length 0 (OpenSim 2.x's start for its deprecated
// muscles, which Sinew keeps): each tendon then takes the whole path and pulls many times its
// maximum isometric force, and the first milliseconds fling the model.
void WarnZeroLengthFibers(const engine::System& system, const engine::State& state) {
  const std::vector<std::string>& names = system.state_variable_names();
  const std::string suffix = "/fiber_length";
  std::vector<std::string> muscles;
  for (size_t i = 0; i < names.size(); ++i) {
    if (names[i].ends_with(suffix) && state.z[static_cast<Eigen::Index>(i)] == 0.0) {
      muscles.push_back(names[i].substr(0, names[i].size() - suffix.size()));
    }
  }
  if (muscles.empty()) return;
  std::cerr << "sinew: warning: " << muscles.size() << " muscle(s) start with fiber length 0 ("
            << muscles.front() << (muscles.size() > 1 ? ", ..." : "")
            << "; OpenSim 2.x's start for its deprecated muscles): each tendon takes the whole "
               "path and pulls many times its maximum force; --equilibrate-muscles (a Forward "
               "setup's solve_for_equilibrium_for_auxiliary_states) or an initial-states file "
               "sets the fibers\n";
}

}  // namespace

engine::State MakeStartState(const engine::System& system, const InitialStates* initial,
                             bool equilibrate_muscles, double t, const std::string& model_path) {
  try {
    engine::State state = engine::MakeDefaultState(system, t);
    if (initial) {
      ApplyInitialStateVariables(*initial, system, state);
      if (equilibrate_muscles) engine::InitializeStateVariables(system, state);
    }
    if (equilibrate_muscles) {
      WarnUnbalancedFibers(system, state);
    } else {
      WarnZeroLengthFibers(system, state);
    }
    return state;
  } catch (const Error& error) {  // e.g. constraints that cannot be assembled: name the model
    if (!error.where().file.empty()) throw;
    throw Error({model_path, 0}, error.component(), error.message());
  }
}

RunTables::RunTables(const engine::System& system, const model::ModelSpec& spec,
                     const TableFiles& files, const contact::NscContactTable* nsc)
    : system_(system), spec_(spec), nsc_(nsc), force_reporter_(system), data_(system) {
  OpenTable(states_, files.states, "states", opensim::StatesLabels(system));
  // OpenSim's Forward tool also writes the states with rotational coordinates' values and
  // speeds in degrees (SimbodyEngine::convertRadiansToDegrees); other columns are unchanged.
  OpenTable(states_degrees_, files.states_degrees, "states_degrees", opensim::StatesLabels(system),
            true);
  degrees_per_unit_.assign(opensim::StatesLabels(system).size(), 1.0);
  for (int c = 0; c < system.num_coordinates(); ++c) {
    for (const model::CoordinateSpec& coordinate : spec.coordinates) {
      if (coordinate.name == system.coordinates()[c].name &&
          coordinate.motion_type == model::MotionType::kRotational) {
        degrees_per_unit_[2 * c] = degrees_per_unit_[2 * c + 1] = 180.0 / std::numbers::pi;
      }
    }
  }
  // OpenSim BodyKinematics positions; the angles are degrees, and the header says so.
  OpenTable(bodies_, files.bodies, "Positions", kinematics::BodyKinematicsLabels(spec), true);
  // forces with appliesForce false are left out, as OpenSim's ForceReporter leaves them out.
  OpenTable(forces_, files.forces, "ForceReporter", force_reporter_.labels());
  OpenTable(controls_, files.controls, "controls", opensim::ControlsLabels(system));
  OpenTable(constraints_, files.constraints, "ConstraintForces",
            opensim::ConstraintForcesLabels(system));
  // Each contact force's force and torque per body and its active contacts, when there are any;
  // then NSC's collision contacts.
  std::vector<std::string> labels = contact::ContactTableLabels(system);
  if (nsc_) labels.insert(labels.end(), nsc_->labels().begin(), nsc_->labels().end());
  if (!labels.empty()) {
    OpenTable(contacts_, files.contacts, "Contacts", std::move(labels));
  }
  X_GB_.resize(system.num_bodies());
}

void RunTables::Record(const engine::State& s) {
  if (states_) {
    opensim::StatesRow(system_, s, row_);
    states_->AppendRow(s.t, row_);
  }
  if (states_degrees_) {
    opensim::StatesRow(system_, s, row_);
    for (size_t i = 0; i < row_.size(); ++i) row_[i] *= degrees_per_unit_[i];
    states_degrees_->AppendRow(s.t, row_);
  }
  if (bodies_) {
    // A fresh system holds the spec's bodies in spec order (stand-ins add none).
    for (int b = 0; b < system_.num_bodies(); ++b) X_GB_[b] = engine::PoseOf(s.bodies[b]);
    bodies_->AppendRow(s.t, kinematics::CalcBodyKinematicsRow(spec_, X_GB_));
  }
  if (forces_) {
    force_reporter_.CalcRow(s, row_);
    forces_->AppendRow(s.t, row_);
  }
  if (controls_) {
    opensim::ControlsRow(s, row_);
    controls_->AppendRow(s.t, row_);
  }
  if (constraints_) {
    // External loads are force elements of the system, so no loads are passed besides them.
    opensim::ConstraintForcesRow(system_, s, nullptr, data_, row_);
    constraints_->AppendRow(s.t, row_);
  }
  if (contacts_) {
    contact::ContactTableRow(system_, s, row_);
    if (nsc_) {
      nsc_->Row(nsc_row_);
      row_.insert(row_.end(), nsc_row_.begin(), nsc_row_.end());
    }
    contacts_->AppendRow(s.t, row_);
  }
}

void RunTables::Finish(const std::string& partial_reason) {
  for (std::optional<io::StorageWriter>* table :
       {&states_, &states_degrees_, &bodies_, &forces_, &controls_, &constraints_, &contacts_}) {
    if (*table) (*table)->Finish(partial_reason);
  }
}

long RunTables::rows() const { return states_ ? states_->rows() : 0; }

void RunWithProgress(engine::Integrator& integrator, engine::State& state, double duration,
                     double report_interval, bool quiet, RunTables& tables, const std::string& out,
                     const std::function<void(const engine::State&)>& also_record) {
  engine::SimulationOptions run;
  run.duration = duration;
  run.report_interval = report_interval;
  const InterruptGuard interrupt;
  run.stop = &interrupt.flag();
  if (!quiet && isatty(fileno(stderr))) run.progress = ShowProgress;
  const engine::SimulationResult result =
      engine::Simulate(integrator, state, run, [&](const engine::State& s) {
        tables.Record(s);
        if (also_record) also_record(s);
      });
  if (run.progress) std::fprintf(stderr, "\n");
  if (result.completed) {
    tables.Finish("");
    return;
  }
  const std::string partial =
      "stopped by " + interrupt.SignalName() + " at t = " + std::to_string(state.t) + " s";
  tables.Finish(partial);
  std::cerr << "sinew: " << partial << ": kept the " << tables.rows() << " rows computed in " << out
            << " (the headers of its tables say status=partial)\n";
  throw ExitRequest{128 + interrupt.Signal()};
}

std::string DescribeSteps(const engine::IntegratorStats& stats) {
  std::string text = std::to_string(stats.steps) + " steps (" + std::to_string(stats.rejected) +
                     " rejected), " + std::to_string(stats.evaluations) + " evaluations";
  if (stats.breakpoints_crossed > 0) {
    text += ", " + std::to_string(stats.breakpoints_crossed) + " spline breakpoint" +
            (stats.breakpoints_crossed == 1 ? "" : "s") + " crossed at a step's end";
  }
  return text;
}

}  // namespace sinew::cli

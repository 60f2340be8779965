// What `simulate` and `forward` share: building the model with its forces, loads and
// excitations; the initial state; the tables streamed while the run computes them; the progress
// bar; and a clean stop on SIGINT/SIGTERM.
#pragma once

#include <sinew/contact/nsc_contact_table.h>
#include <sinew/engine/dynamics.h>
#include <sinew/engine/force_reporter.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/simulation.h>
#include <sinew/engine/state.h>
#include <sinew/engine/system.h>
#include <sinew/io/storage_writer.h>
#include <sinew/model/model_spec.h>
#include <sinew/opensim/parser.h>
#include <sinew/paths/geometry_path.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "apps/sinew/contact_options.h"
#include "apps/sinew/initial_states.h"

namespace sinew::cli {

/// How the model of a run is built (the parser's options).
struct ModelOptions {
  std::string model_path;  ///< names the model in messages
  bool strict = false;     ///< anything approximated or left out is an error
  bool quiet = false;      ///< no note about the Report's warnings
  bool activate_actuators = false;
  std::string controls;                      ///< ControlSet file ("" for none)
  std::vector<std::string> external_loads;   ///< ExternalLoads files
  std::vector<std::string> disabled_forces;  ///< forces left out by name
  std::vector<std::string> excitations;      ///< --excitation NAME=KIND:ARGS
  /// Muscles start at muscle-tendon equilibrium (`--equilibrate-muscles`, the Forward tool's
  /// solve_for_equilibrium_for_auxiliary_states).
  bool equilibrate_muscles = false;
  /// OLD=NEW: forces of class OLD are read as class NEW (`--rename-force-class`).
  std::vector<std::string> renamed_force_classes;
  /// When cylinders refine their tangent points (`--cylinder-refinement`).
  paths::CylinderRefinement cylinder_refinement = paths::CylinderRefinement::kSeveralWraps;
  ContactOptions contact;  ///< --collision, --contact, --ground-plane, the material
  /// Folders searched for mesh files (ContactMesh files too) after the model's (--geometry-dir).
  std::vector<std::string> geometry_dirs;
};

/// A parsed model: the parser (its Report, its controller) and the finalized system.
struct BuiltModel {
  opensim::OpenSimParser parser;
  std::unique_ptr<engine::System> system;
};

/// Warns about (or, strict, refuses) what is not simulated, parses `spec` with `options` into a
/// finalized system, sets the excitations, and notes the Report's warnings on stderr.
BuiltModel BuildModel(const model::ModelSpec& spec, const ModelOptions& options);

/// The state a run starts from at `t`: the default state (assembled onto the constraints;
/// muscles at equilibrium when `equilibrate_muscles`), then the auxiliary state variables the
/// `initial` row names (may be null), then, with `equilibrate_muscles`, muscle equilibrium again
/// at the row's activations (OpenSim: the states file first, then equilibrium); a warning names
/// each muscle whose fiber had to start at its minimum length. An error without a file names
/// the model.
engine::State MakeStartState(const engine::System& system, const InitialStates* initial,
                             bool equilibrate_muscles, double t, const std::string& model_path);

/// The output files of a run; an empty name is not written.
struct TableFiles {
  std::string states;          ///< OpenSim 4 state labels
  std::string states_degrees;  ///< the same, rotational coordinates in degrees (OpenSim's .mot)
  std::string bodies;          ///< BodyKinematics positions
  std::string forces;          ///< ForceReporter
  std::string controls;        ///< each actuator's control (OpenSim's controls table)
  std::string constraints;     ///< constraint forces
  std::string contacts;  ///< contact forces per body; written only when the model has some, or NSC
};

/// What the integrator did, for a run's summary: "N steps (R rejected), E evaluations", and how
/// many spline breakpoints rk45 crossed at a step's end when it did.
std::string DescribeSteps(const engine::IntegratorStats& stats);

/// The tables of a run, streamed to disk row by row (bounded memory) and committed by Finish.
class RunTables {
 public:
  /// Opens every table named in `files` for `system` (built from `spec`). With `nsc` (an NSC
  /// run's collision contacts, which must outlive the tables) its columns follow the contact
  /// forces' in the contacts table.
  RunTables(const engine::System& system, const model::ModelSpec& spec, const TableFiles& files,
            const contact::NscContactTable* nsc = nullptr);
  /// Appends one row per table for `state`.
  void Record(const engine::State& state);
  /// Commits every table; a non-empty `partial_reason` marks them status=partial.
  void Finish(const std::string& partial_reason);
  /// Rows written so far.
  long rows() const;
  /// True when a contacts table is written (TableFiles::contacts named and contact forces exist).
  bool writes_contacts() const { return contacts_.has_value(); }

 private:
  const engine::System& system_;
  const model::ModelSpec& spec_;
  const contact::NscContactTable* nsc_;
  engine::ForceReporter force_reporter_;
  engine::Data data_;
  std::optional<io::StorageWriter> states_, states_degrees_, bodies_, forces_, controls_,
      constraints_, contacts_;
  std::vector<double> degrees_per_unit_;  // per states column: 180/pi (rotational) or 1
  std::vector<double> row_, nsc_row_;
  std::vector<Transform> X_GB_;
};

/// Runs engine::Simulate for `duration` from `state` with a report every `report_interval`,
/// recording each reported state in `tables` and then `also_record` (may be empty), with a
/// progress bar on stderr unless `quiet` or stderr is not a terminal. SIGINT or SIGTERM stops
/// the run: the tables are committed as partial, a message names `out` and the rows kept, and
/// ExitRequest{128 + signal} is thrown. Otherwise the tables are committed complete.
void RunWithProgress(engine::Integrator& integrator, engine::State& state, double duration,
                     double report_interval, bool quiet, RunTables& tables, const std::string& out,
                     const std::function<void(const engine::State&)>& also_record = {});

}  // namespace sinew::cli

// ModelHandle: what sinew.Model holds on the C++ side. The file's spec, the parser that built
// the System (its Report and the excitation controller), and the System, shared read-only by
// every State, Simulator and Batch made from the model (a finalized System never changes).
#pragma once

#include <sinew/contact/collision_material.h>
#include <sinew/engine/nsc_integrator.h>
#include <sinew/engine/state.h>
#include <sinew/engine/system.h>
#include <sinew/model/model_spec.h>
#include <sinew/model/parameter_overrides.h>
#include <sinew/opensim/parser.h>

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sinew::python {

/// The options of sinew.load, kept so a model can be built again from its file (with initial
/// states or a controls file applied, as `sinew simulate` applies them before parsing).
struct LoadOptions {
  std::string visualization = "none";  ///< "none", "primitives" or "mesh"
  bool collision = false;
  std::string contact = "nsc";  ///< "nsc" or "smc"
  /// NSC's stepper (with collision and contact "nsc"): its impulse solver "apgd" or
  /// "gauss-seidel", and the rest of engine::NscSettings, as `sinew simulate --nsc-*`.
  std::string nsc_solver = "apgd";
  engine::NscSettings nsc;  ///< its solver.method is set from nsc_solver
  bool strict = false;
  /// When cylinders refine their tangent points: "several-wraps" (OpenSim 4.4.1+),
  /// "opensim-4.4" (OpenSim 4.4.0) or "always"
  /// (paths::CylinderRefinement), as `sinew simulate --cylinder-refinement`.
  std::string cylinder_refinement = "several-wraps";
  std::string controls_file;  ///< an OpenSim ControlSet file, "" for none
  /// Folders searched for mesh files (ContactMesh files too) after the model's own, as
  /// `--geometry-dir` (OpenSimParser::AddGeometryDir).
  std::vector<std::string> geometry_dirs;
  /// Property overrides applied to the spec before the System is built
  /// (model::ApplyParameterOverrides), in the order given.
  std::vector<model::ParameterOverride> parameters;
  /// The collision contact's default material (OpenSimParser::SetContactMaterial), as
  /// `--friction`, `--kt`, ...; and SMC's friction slip speed (`--slip-speed`).
  std::optional<contact::CollisionMaterial> contact_material;
  std::optional<double> slip_speed;
  /// OpenSim ExternalLoads files (OpenSimParser::AddExternalLoads), as `--external-loads`.
  std::vector<std::string> external_loads;
  /// Forces left out by name (OpenSimParser::DisableForce), as `--disable-force`.
  std::vector<std::string> disabled_forces;
  /// Forces of class `first` are read as class `second` (OpenSimParser::RenameForceClass), as
  /// `--rename-force-class OLD=NEW`.
  std::vector<std::pair<std::string, std::string>> renamed_force_classes;
  /// ForceSet files appended to (or, replace_force_set, replacing) the model's forces, as a
  /// Forward setup's force_set_files (io::ForceSetFiles).
  std::vector<std::string> force_set_files;
  bool replace_force_set = false;
  /// The time a run starts at (a Forward setup's initial_time): the default states' time, and
  /// with an initial-states table the row OpenSim's Forward tool takes for it
  /// (opensim::ForwardStartRow); none: 0, and the table's first row.
  std::optional<double> start_time;
};

/// An initial-states table as ModelHandle::Rebuild took it.
struct InitialStatesTable {
  io::Storage table;  ///< as read, rotational columns in radians
  int row = 0;        ///< the row used (the first, or LoadOptions::start_time's)
  /// Columns naming no simulated coordinate value or speed nor state variable (an error when
  /// strict).
  std::vector<std::string> unused_labels;
  Diagnostics warnings;  ///< what the reader read leniently, and the table check's warnings
};

/// A parsed model. Immutable after Build; shared by the objects made from it.
class ModelHandle {
 public:
  /// Reads `path` and builds its System as `sinew simulate` does (io::ReadOsim, the
  /// options' parameter overrides, then OpenSimParser::ParseSpec). Throws sinew::Error.
  static std::shared_ptr<ModelHandle> Load(const std::string& path, const LoadOptions& options);
  /// The same file built again as `sinew simulate --initial-states F --controls C` builds it:
  /// one row of the states table `states_file` ("" for none) as the coordinates' defaults
  /// (opensim::ApplyInitialStates; t0() is the row's time; `states` gets the table, checked by
  /// opensim::CheckTableFor, with what it could not use), driven by the ControlSet file
  /// `controls_file` ("" for the model's own controllers). `read`: the table already read from
  /// `states_file` (a Forward run's plan has it), or null to read it.
  std::shared_ptr<ModelHandle> Rebuild(const std::string& states_file,
                                       const std::string& controls_file, InitialStatesTable& states,
                                       const io::Storage* read = nullptr) const;

  const std::string& path() const { return path_; }
  const LoadOptions& options() const { return options_; }
  const engine::System& system() const { return *system_; }
  const opensim::OpenSimParser& parser() const { return parser_; }
  const model::ModelSpec& spec() const { return parser_.GetSpec(); }
  /// Start time of default states (the initial-states row's time, else 0).
  double t0() const { return t0_; }
  /// Names of the coordinates, in System order (the columns of q and u).
  std::vector<std::string> CoordinateNames() const;
  /// Names of the actuators, in the order of their inputs (engine::State::inputs).
  const std::vector<std::string>& actuators() const { return actuators_; }

  /// The default state at t0 (engine::MakeDefaultState); an error names the model's file.
  engine::State DefaultState() const;
  /// Index of coordinate `name`; throws sinew::Error naming the model for an unknown one.
  int CoordinateIndex(const std::string& name) const;

 private:
  /// The file's spec with the parameter overrides applied.
  static model::ModelSpec ReadSpec(const std::string& path, const LoadOptions& options);
  static std::shared_ptr<ModelHandle> Build(const std::string& path, model::ModelSpec spec,
                                            const LoadOptions& options, double t0);

  std::string path_;
  LoadOptions options_;
  opensim::OpenSimParser parser_;
  std::unique_ptr<engine::System> system_;
  double t0_ = 0.0;
  std::vector<std::string> actuators_;
};

using ModelPtr = std::shared_ptr<ModelHandle>;

}  // namespace sinew::python

#include "model_handle.h"

#include <sinew/common/error.h>
#include <sinew/engine/assemble.h>
#include <sinew/io/osim_reader.h>
#include <sinew/io/storage.h>
#include <sinew/opensim/initial_states.h>
#include <sinew/opensim/table_checks.h>

#include <cmath>
#include <sstream>
#include <tuple>

namespace sinew::python {

std::shared_ptr<ModelHandle> ModelHandle::Load(const std::string& path,
                                               const LoadOptions& options) {
  return Build(path, ReadSpec(path, options), options, options.start_time.value_or(0.0));
}

model::ModelSpec ModelHandle::ReadSpec(const std::string& path, const LoadOptions& options) {
  model::ModelSpec spec =
      io::ReadOsim(path, io::ForceSetFiles{options.force_set_files, options.replace_force_set});
  model::ApplyParameterOverrides(spec, options.parameters);
  return spec;
}

std::shared_ptr<ModelHandle> ModelHandle::Build(const std::string& path, model::ModelSpec spec,
                                                const LoadOptions& options, double t0) {
  if (options.contact != "nsc" && options.contact != "smc") {
    throw Error({path, 0}, "",
                "contact must be \"nsc\" or \"smc\", not \"" + options.contact + "\"");
  }
  if (!paths::FindCylinderRefinement(options.cylinder_refinement)) {
    throw Error({path, 0}, "",
                "cylinder_refinement must be \"several-wraps\", \"opensim-4.4\" or \"always\", "
                "not \"" +
                    options.cylinder_refinement + "\"");
  }
  // NSC's stepper: as `sinew simulate --nsc-*` checks it, and only where it runs.
  engine::NscSettings nsc = options.nsc;
  const auto method = engine::FindContactSolverMethod(options.nsc_solver);
  if (!method) {
    throw Error(
        {path, 0}, "",
        "nsc_solver must be \"apgd\" or \"gauss-seidel\", not \"" + options.nsc_solver + "\"");
  }
  nsc.solver.method = *method;
  if (nsc.solver.max_iterations < 1) {
    throw Error({path, 0}, "",
                "nsc_iterations must be >= 1, not " + std::to_string(nsc.solver.max_iterations));
  }
  for (const auto& [name, value, positive] :
       {std::tuple<const char*, double, bool>{"nsc_tolerance", nsc.solver.tolerance, true},
        {"nsc_max_recovery_speed", nsc.max_recovery_speed, false},
        {"nsc_min_bounce_speed", nsc.min_bounce_speed, false}}) {
    if (!std::isfinite(value) || (positive ? !(value > 0.0) : !(value >= 0.0))) {
      std::ostringstream text;
      text << name << " must be a finite number " << (positive ? "> 0" : ">= 0") << ", not "
           << value;
      throw Error({path, 0}, "", text.str());
    }
  }
  const engine::NscSettings defaults;
  const bool nsc_set = nsc.solver.method != defaults.solver.method ||
                       nsc.solver.max_iterations != defaults.solver.max_iterations ||
                       nsc.solver.tolerance != defaults.solver.tolerance ||
                       nsc.max_recovery_speed != defaults.max_recovery_speed ||
                       nsc.min_bounce_speed != defaults.min_bounce_speed;
  if (nsc_set && !(options.collision && options.contact == "nsc")) {
    throw Error({path, 0}, "",
                "the nsc_* settings are NSC's stepper's: they need collision=True and "
                "contact=\"nsc\"");
  }
  // The collision contact's material and slip speed: checked as the CLI checks them, and only
  // where they act.
  if ((options.contact_material || options.slip_speed) && !options.collision) {
    throw Error({path, 0}, "",
                "contact_material and slip_speed are the collision contact's: they need "
                "collision=True");
  }
  if (options.slip_speed && options.contact != "smc") {
    throw Error({path, 0}, "",
                "slip_speed is SMC's friction regularization: it needs contact=\"smc\"");
  }
  if (options.slip_speed && !(std::isfinite(*options.slip_speed) && *options.slip_speed > 0.0)) {
    std::ostringstream text;
    text << "slip_speed must be a finite number > 0, not " << *options.slip_speed;
    throw Error({path, 0}, "", text.str());
  }
  if (options.contact_material) {
    contact::CheckMaterial(*options.contact_material, {path, 0}, "contact_material");
  }
  auto handle = std::shared_ptr<ModelHandle>(new ModelHandle());
  handle->path_ = path;
  handle->options_ = options;
  handle->t0_ = t0;
  opensim::OpenSimParser& parser = handle->parser_;
  parser.SetVisualizationType(viz::ParseVisType(options.visualization));
  if (options.collision) parser.EnableCollision();
  parser.SetContactMethod(options.contact == "smc" ? opensim::ContactMethod::kSmc
                                                   : opensim::ContactMethod::kNsc);
  parser.SetNscSettings(nsc);
  if (options.contact_material) parser.SetContactMaterial(*options.contact_material);
  if (options.slip_speed) parser.SetFrictionSlipSpeed(*options.slip_speed);
  parser.SetStrict(options.strict);
  parser.SetCylinderRefinement(*paths::FindCylinderRefinement(options.cylinder_refinement));
  parser.SetControlsFile(options.controls_file);
  for (const std::string& dir : options.geometry_dirs) parser.AddGeometryDir(dir);
  for (const std::string& file : options.external_loads) parser.AddExternalLoads(file);
  for (const std::string& name : options.disabled_forces) parser.DisableForce(name);
  for (const auto& [from, to] : options.renamed_force_classes) parser.RenameForceClass(from, to);
  handle->system_ = std::make_unique<engine::System>();
  parser.ParseSpec(*handle->system_, std::move(spec));
  handle->system_->Finalize();
  // Each actuator owns one input; list them in input order.
  handle->actuators_.assign(handle->system_->num_inputs(), "");
  for (const auto& [key, force] : parser.GetReport().forces()) {
    if (force.actuator && force.input >= 0) handle->actuators_[force.input] = key;
  }
  return handle;
}

std::shared_ptr<ModelHandle> ModelHandle::Rebuild(const std::string& states_file,
                                                  const std::string& controls_file,
                                                  InitialStatesTable& states,
                                                  const io::Storage* read) const {
  // The overrides first: an initial-states row then sets the coordinates' defaults over them.
  model::ModelSpec spec = ReadSpec(path_, options_);
  double t0 = options_.start_time.value_or(0.0);
  states = InitialStatesTable{};
  if (!states_file.empty()) {
    states.table = read ? *read : io::ReadStorage(states_file);
    states.warnings = states.table.notes;
    const Diagnostics checked = opensim::CheckTableFor(states.table, states_file, spec);
    states.warnings.insert(states.warnings.end(), checked.begin(), checked.end());
    if (options_.start_time && states.table.NumRows() > 0) {
      states.row = opensim::ForwardStartRow(states.table, *options_.start_time);
    }
    const opensim::InitialStates initial =
        opensim::ApplyInitialStates(states.table, states_file, spec, states.row);
    states.unused_labels = initial.unused_labels;
    t0 = initial.t0;
    if (options_.strict && !states.unused_labels.empty()) {
      throw Error({states_file, 0}, states.unused_labels.front(),
                  std::to_string(states.unused_labels.size()) +
                      " column(s) name no coordinate value or speed or state variable that is "
                      "simulated (strict)");
    }
  }
  LoadOptions options = options_;
  options.controls_file = controls_file;
  return Build(path_, std::move(spec), options, t0);
}

engine::State ModelHandle::DefaultState() const {
  try {
    return engine::MakeDefaultState(*system_, t0_);
  } catch (const Error& error) {  // e.g. constraints that cannot be assembled: name the model
    if (!error.where().file.empty()) throw;
    throw Error({path_, 0}, error.component(), error.message());
  }
}

std::vector<std::string> ModelHandle::CoordinateNames() const {
  std::vector<std::string> names;
  for (const auto& c : system_->coordinates()) names.push_back(c.name);
  return names;
}

int ModelHandle::CoordinateIndex(const std::string& name) const {
  const auto& coordinates = system_->coordinates();
  for (size_t i = 0; i < coordinates.size(); ++i) {
    if (coordinates[i].name == name) return static_cast<int>(i);
  }
  throw Error({path_, 0}, name, "the model has no coordinate of this name");
}

}  // namespace sinew::python

#include <sinew/common/text.h>
#include <sinew/functions/constant.h>
#include <sinew/io/osim_reader.h>
#include <sinew/io/read_controls.h>
#include <sinew/opensim/build_system.h>
#include <sinew/opensim/internal/collision_builder.h>
#include <sinew/opensim/internal/constraint_registry.h>
#include <sinew/opensim/internal/force_registry.h>
#include <sinew/opensim/parser.h>
#include <sinew/opensim/support.h>

#include <algorithm>
#include <iostream>

namespace sinew::opensim {
namespace {

// The name a component is reported under: the last segment of its path, which the reader has
// already made unique (a repeated joint name `sph1` becomes `/jointset/sph1_2`, with a warning).
std::string ReportName(const std::string& path, const std::string& name) {
  const size_t slash = path.find_last_of('/');
  return path.empty() || slash == std::string::npos ? name : path.substr(slash + 1);
}

// Replaces the joints the engine cannot build by stand-ins (ReplaceWithStandIns), reporting
// each. Returns which joints were replaced.
std::vector<bool> ReplaceUnknownJoints(model::ModelSpec& spec, Report& report) {
  std::vector<bool> replaced(spec.joints.size(), false);
  for (const StandIn& standin : ReplaceWithStandIns(spec)) {
    const model::JointSpec& joint = spec.joints[standin.joint];
    replaced[standin.joint] = true;
    report.AddWarning(
        {joint.where, joint.path,
         "joint type '" + joint.type +
             "' cannot be simulated: replaced by a spherical stand-in at its frames"});
    for (int c : standin.coordinates) {
      report.AddNotSimulated(spec.coordinates[c].path + ": coordinate of stand-in joint");
    }
  }
  return replaced;
}

}  // namespace

void OpenSimParser::EnableCollision(int family_1, int family_2) {
  collision_enabled_ = true;
  collision_settings_.family_1 = family_1;
  collision_settings_.family_2 = family_2;
}

void OpenSimParser::AddEnvironmentBox(const std::string& name, const Transform& X_GS,
                                      const Vec3& half_extents) {
  if (!(half_extents.minCoeff() > 0.0))
    throw Error(SourceLocation{}, name, "an environment box needs half extents > 0");
  contact::CollisionGeometry box;
  box.name = name;
  box.kind = contact::CollisionShapeKind::kBox;
  box.X_BS = X_GS;
  box.half_extents = half_extents;
  collision_settings_.environment.push_back(box);
}

std::unique_ptr<engine::System> OpenSimParser::Parse(const std::string& filename,
                                                     ContactMethod method) {
  auto system = std::make_unique<engine::System>();
  contact_method_ = method;
  Parse(*system, filename);
  system->Finalize();
  return system;
}

void OpenSimParser::Parse(engine::System& system, const std::string& filename) {
  ParseSpec(system, io::ReadOsim(filename));
}

void OpenSimParser::ParseSpec(engine::System& system, model::ModelSpec spec) {
  spec_ = std::move(spec);
  for (model::ForceSpec& force : spec_.forces) {
    for (const auto& [from, to] : force_class_renames_) {
      if (force.type == from) force.type = to;
    }
  }
  report_ = Report();
  collision_ = contact::CollisionModel();
  for (const Diagnostic& w : spec_.warnings) report_.AddWarning(w);

  if (system.num_bodies() > 1 && !system.gravity().isApprox(spec_.gravity)) {
    report_.AddWarning({SourceLocation{spec_.file, 0}, "/gravity",
                        "the system already had another gravity; the file's replaces it"});
  }
  system.SetGravity(spec_.gravity);

  model::ModelSpec built = spec_;
  const std::vector<bool> standin = ReplaceUnknownJoints(built, report_);
  Diagnostics notes;
  const SpecToSystem map = BuildInto(built, system, BuildOptions{}, &notes);
  for (Diagnostic& note : notes) report_.AddWarning(std::move(note));

  for (size_t b = 1; b < built.bodies.size(); ++b) {
    report_.AddBody({built.bodies[b].name, map.bodies[b]});
  }
  for (size_t j = 0; j < built.joints.size(); ++j) {
    const int engine_joint = map.joints[j];
    report_.AddJoint({ReportName(built.joints[j].path, built.joints[j].name), built.joints[j].type,
                      engine_joint, system.joints()[engine_joint].form, standin[j]});
  }
  BuildConstraints(system, map.bodies, map.coordinates);
  BuildForces(system, map.bodies, map.coordinates);
  AssignExcitations();
  if (collision_enabled_) {
    collision_ = internal::BuildCollision(spec_, collision_settings_, disabled_forces_,
                                          geometry_dirs_, report_);
    if (contact_method_ == ContactMethod::kSmc) {
      internal::AddSmoothContact(system, spec_, collision_, map.bodies,
                                 collision_settings_.slip_speed, report_);
    } else if (const std::vector<std::string> unused = internal::SmcOnlyParametersSet(collision_);
               !unused.empty()) {
      std::string names;
      for (const std::string& name : unused) names += (names.empty() ? "" : ", ") + name;
      report_.AddWarning({SourceLocation{spec_.file, 0}, "contact material",
                          names + ": SMC's contact parameters, which NSC ignores (it uses the "
                                  "friction and the restitution)"});
    }
  }
  for (std::string& line : ListNotSimulated(spec_, disabled_forces_)) {
    // Contact geometry that collides is simulated, though no contact force names it.
    const bool collides =
        std::any_of(collision_.geometry.begin(), collision_.geometry.end(),
                    [&](const contact::CollisionGeometry& g) {
                      return line.starts_with("/contactgeometryset/" + g.name + ":");
                    });
    if (!collides) report_.AddNotSimulated(std::move(line));
  }
  scene_ = viz::VisualScene();
  if (vis_type_ != VisType::kNone) {
    viz::VisualOptions options;
    options.mode = vis_type_;
    options.geometry_dirs = geometry_dirs_;
    scene_ = viz::BuildVisualScene(spec_, options);
    for (const Diagnostic& w : scene_.warnings) report_.AddWarning(w);
  }
  if (verbose_) report_.Print(std::cerr);
  CheckStrict();
}

void OpenSimParser::BuildConstraints(engine::System& system, const std::vector<int>& body_map,
                                     const std::vector<int>& coordinate_map) {
  for (const model::ConstraintSpec& constraint : spec_.constraints) {
    ConstraintInfo info{ReportName(constraint.path, constraint.name), constraint.type, nullptr};
    if (IsConstraintSimulated(constraint)) {
      auto built = internal::BuildConstraint(spec_, constraint, body_map, coordinate_map);
      system.AddConstraint(built);
      info.constraint = std::move(built);
    }
    report_.AddConstraint(std::move(info));
  }
}

void OpenSimParser::BuildForces(engine::System& system, const std::vector<int>& body_map,
                                const std::vector<int>& coordinate_map) {
  for (const model::ForceSpec& force : spec_.forces) {
    BuildOneForce(system, force, body_map, coordinate_map, nullptr);
  }
  for (const std::string& file : external_loads_files_) {
    const io::ExternalLoads loads = io::ReadExternalLoads(file);
    for (const Diagnostic& note : loads.notes) report_.AddWarning(note);
    for (const model::ForceSpec& force : loads.forces) {
      BuildOneForce(system, force, body_map, coordinate_map, &loads);
    }
  }
  CheckDisabledNames();
}

void OpenSimParser::BuildOneForce(engine::System& system, const model::ForceSpec& force,
                                  const std::vector<int>& body_map,
                                  const std::vector<int>& coordinate_map,
                                  const io::ExternalLoads* external_loads) {
  ForceInfo info{ReportName(force.path, force.name), force.type, nullptr, nullptr, -1, ""};
  const bool by_name = std::find(disabled_forces_.begin(), disabled_forces_.end(), info.name) !=
                       disabled_forces_.end();
  if (by_name) {
    info.disabled = "disabled by name";
  } else if (!force.applies_force) {
    info.disabled = "appliesForce false in the file";
  } else if (IsForceSimulated(force)) {
    Diagnostics notes;
    auto element =
        internal::BuildForce(spec_, force, body_map, coordinate_map, external_loads, &notes,
                             equilibrate_muscles_, cylinder_refinement_, &geometry_dirs_);
    for (Diagnostic& note : notes) report_.AddWarning(std::move(note));
    const int k = system.AddForceElement(element);
    info.load = element;
    if (internal::FindForceType(force.type)->actuator) {
      info.actuator = std::static_pointer_cast<const forces::Actuator>(element);
      info.input = system.InputBegin(k);
      info.excitation_source = "default 0";
    }
  }
  report_.AddForce(std::move(info));
}

void OpenSimParser::CheckDisabledNames() const {
  std::vector<std::string> names;
  for (const auto& [key, info] : report_.forces()) names.push_back(info.name);
  for (const std::string& name : disabled_forces_) {
    if (std::find(names.begin(), names.end(), name) != names.end()) continue;
    const std::vector<std::string> close = FindCloseNames(name, names);
    const std::vector<std::string>& shown = close.empty() ? names : close;
    constexpr size_t kMaxShown = 10;
    std::string list;
    for (size_t i = 0; i < shown.size() && i < kMaxShown; ++i) {
      list += (i == 0 ? "" : ", ") + shown[i];
    }
    if (shown.size() > kMaxShown) list += ", ...";
    throw Error(SourceLocation{spec_.file, 0}, name,
                "cannot disable: no force has this name (" +
                    std::string(close.empty() ? "the forces: " : "close names: ") +
                    (list.empty() ? "the model has none" : list) + ")");
  }
}

void OpenSimParser::AssignExcitations() {
  auto controller = std::make_shared<forces::ExcitationController>();
  // Lowest precedence first; each source overrides the previous ones.
  for (const model::ControllerSpec& spec_controller : spec_.controllers) {
    if (!IsControllerSimulated(spec_controller)) continue;
    for (size_t i = 0; i < spec_controller.actuators.size(); ++i) {
      // 3.x files list actuator names (actuator_list); 4.x files socket paths
      // (socket_actuators, e.g. /forceset/act): the Report key is the path's last segment.
      const std::string& entry = spec_controller.actuators[i];
      ForceInfo* info = report_.MutableForce(entry);
      if (!info) info = report_.MutableForce(ReportName(entry, entry));
      if (!info || !info->actuator) {
        report_.AddWarning({spec_controller.where, "/controllerset/" + spec_controller.name,
                            "controls '" + spec_controller.actuators[i] +
                                "', which is not a simulated actuator: ignored"});
        continue;
      }
      controller->Set(info->input, spec_controller.functions[i]);
      info->excitation_source = "PrescribedController " + spec_controller.name;
    }
  }
  if (activate_actuators_) {
    auto one = std::make_shared<functions::Constant>(1.0);
    for (const auto& [key, info] : report_.forces()) {
      if (!info.actuator) continue;
      controller->Set(info.input, one);
      report_.MutableForce(key)->excitation_source = "ActivateActuators";
    }
  }
  if (!controls_file_.empty()) {
    for (auto& [name, function] : io::ReadControlSet(controls_file_)) {
      ForceInfo* info = report_.MutableForce(name);
      if (!info || !info->actuator) {
        report_.AddWarning({SourceLocation{controls_file_, 0}, name,
                            "the controls file drives '" + name +
                                "', which is not a simulated actuator: ignored"});
        continue;
      }
      if (info->excitation_source.starts_with("PrescribedController")) {
        // OpenSim adds the controls of every controller of an actuator; Sinew takes one.
        report_.AddWarning({SourceLocation{controls_file_, 0}, name,
                            "the controls file replaces the " + info->excitation_source + " of '" +
                                name + "' (OpenSim would add the two controls)"});
      }
      controller->Set(info->input, function);
      info->excitation_source = "controls file";
    }
  }
  controller_ = std::move(controller);
}

void OpenSimParser::SetExcitationFunction(const std::string& actuator_name,
                                          functions::FunctionPtr excitation) {
  ForceInfo* info = report_.MutableForce(actuator_name);
  if (!info || !info->actuator) {
    throw Error(SourceLocation{spec_.file, 0}, actuator_name,
                info ? "is not a simulated actuator (" + info->type + ")"
                     : "no actuator of this name was parsed");
  }
  // A new controller: one already handed out (GetController) never changes under a running
  // simulation.
  auto controller = std::make_shared<forces::ExcitationController>(*controller_);
  controller->Set(info->input, std::move(excitation));
  controller_ = std::move(controller);
  info->excitation_source = "set by user";
}

void OpenSimParser::CheckStrict() const {
  if (!strict_) return;
  if (!report_.warnings().empty()) {
    const Diagnostic& w = report_.warnings().front();
    throw Error(w.where, w.component,
                w.message + " (--strict: " + std::to_string(report_.warnings().size()) +
                    " approximation(s) or warning(s) in all)");
  }
  if (!report_.not_simulated().empty()) {
    throw Error(SourceLocation{spec_.file, 0}, "",
                "--strict: " + std::to_string(report_.not_simulated().size()) +
                    " element(s) not simulated, first: " + report_.not_simulated().front());
  }
}

}  // namespace sinew::opensim

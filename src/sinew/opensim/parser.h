// sinew::OpenSimParser: the API of the seed report (Chrono's ChParserOpenSim, TR-2017-08),
// on top of the reader (io/) and the engine: parse an .osim file into an engine::System,
// with a Report of everything built, actuators driven by excitation functions, and options for
// visualization and collision.
#pragma once

#include <sinew/contact/collision_model.h>
#include <sinew/engine/nsc_integrator.h>
#include <sinew/engine/system.h>
#include <sinew/forces/actuator.h>
#include <sinew/forces/excitation_controller.h>
#include <sinew/functions/function.h>
#include <sinew/io/external_loads.h>
#include <sinew/model/model_spec.h>
#include <sinew/opensim/collision_settings.h>
#include <sinew/opensim/report.h>
#include <sinew/paths/geometry_path.h>
#include <sinew/viz/visual_scene.h>

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace sinew::opensim {

using contact::ContactMethod;
using viz::VisType;

/// Parses OpenSim models into engine systems. Options are set before Parse; excitations after.
/// A parser holds no global state: parse as many files, as often, into as many systems as you
/// like; each Parse replaces the Report with that of the new file.
class OpenSimParser {
 public:
  OpenSimParser() = default;

  /// Visual assets to make for the parsed bodies (default NONE): see GetVisualScene().
  void SetVisualizationType(VisType type) { vis_type_ = type; }
  VisType GetVisualizationType() const { return vis_type_; }
  /// A folder searched for mesh files (visual meshes and ContactMesh files) after the model's
  /// folder and its Geometry/ subfolder (then $SINEW_GEOMETRY_PATH). May be called several times.
  void AddGeometryDir(const std::string& dir) { geometry_dirs_.push_back(dir); }
  /// Creates collision shapes (cylinders along each body's segments, as in PRIMITIVES, and the
  /// model's ContactSphere, ContactHalfSpace, ContactCylinder, ContactEllipsoid and ContactMesh)
  /// with bodies in two alternating families by tree depth (the seed's); a body never collides
  /// with its parent or children, every other pair may collide (default: off). docs/contact.md.
  void EnableCollision(int family_1 = 1, int family_2 = 2);
  /// How collisions are treated (default NSC, the seed's): SMC adds the force element
  /// "smc_contact" (contact::SmoothCollisionForce) to the system; NSC leaves the contacts to
  /// the NSC time stepper. Parse(filename, method) sets it too.
  void SetContactMethod(ContactMethod method) { contact_method_ = method; }
  /// Adds the ground plane y = `height` (the solid below) to the environment (with collision).
  void SetGroundPlane(double height) { collision_settings_.ground_plane = height; }
  /// Adds a box fixed to ground (pose X_GS of its centre, half extents in m) to the
  /// environment, named `name` (for SetContactMaterial), e.g. an incline.
  void AddEnvironmentBox(const std::string& name, const Transform& X_GS, const Vec3& half_extents);
  /// The default contact material of the collision shapes (docs/contact.md gives its defaults).
  void SetContactMaterial(const contact::CollisionMaterial& material) {
    collision_settings_.material = material;
  }
  /// The material of the shapes of the body, contact geometry or environment shape `name`.
  void SetContactMaterial(const std::string& name, const contact::CollisionMaterial& material) {
    collision_settings_.overrides.emplace_back(name, material);
  }
  /// SMC's friction regularization speed v_s (m/s, default 1e-3): docs/contact.md.
  void SetFrictionSlipSpeed(double speed) { collision_settings_.slip_speed = speed; }
  /// The settings of NSC's time stepper (its impulse solver's method, iterations and
  /// tolerance; its recovery and bounce speeds) that runs of an NSC model use
  /// (opensim::MakeRunIntegrator; default engine::NscSettings{}): docs/contact.md.
  void SetNscSettings(const engine::NscSettings& settings) { nsc_settings_ = settings; }
  const engine::NscSettings& GetNscSettings() const { return nsc_settings_; }
  /// Prints what is built, and every warning, to stderr while parsing (default: off).
  void SetVerbose(bool verbose) { verbose_ = verbose; }
  /// With true, every actuator starts with the constant excitation 1 (default: 0, OpenSim's
  /// philosophy), overriding the model's own controllers.
  void ActivateActuators(bool activate) { activate_actuators_ = activate; }
  /// With true, anything approximated, substituted or not simulated is an error.
  void SetStrict(bool strict) { strict_ = strict; }
  /// A ControlSet file (OpenSim's `*_controls.xml`) whose controls drive the actuators they
  /// name; it overrides ActivateActuators and the model's controllers. "" for none.
  void SetControlsFile(const std::string& file) { controls_file_ = file; }
  /// Adds the ExternalForces of an OpenSim ExternalLoads file (`<ExternalLoads>`, its
  /// `datafile` read relative to the file) to every later Parse, after the model's own forces.
  /// May be called several times. Parse throws sinew::Error (file, line, force) for a bad file.
  void AddExternalLoads(const std::string& file) { external_loads_files_.push_back(file); }
  /// Leaves the force named `name` (in the model's ForceSet or an ExternalLoads file) out of
  /// every later Parse; the Report lists it as disabled. May be called several times. Parse
  /// throws sinew::Error, listing close names, when no force has this name.
  void DisableForce(const std::string& name) { disabled_forces_.push_back(name); }
  /// With true, every muscle's fiber length starts at muscle-tendon equilibrium for its
  /// activation and the initial pose (OpenSim's equilibrateMuscles, the Forward tool's
  /// solve_for_equilibrium_for_auxiliary_states), computed whenever a default state is made or
  /// engine::InitializeStateVariables is called; a muscle without an equilibrium makes that an
  /// error naming it. Default false: the file's default_fiber_length (or loaded states).
  void EquilibrateMuscles(bool equilibrate) { equilibrate_muscles_ = equilibrate; }
  /// Which OpenSim's WrapCylinder rule the paths of muscles and other path forces follow in
  /// every later Parse: OpenSim 4.4's (the default) or, with kAlways, that of every earlier
  /// OpenSim, to compare with results those versions wrote (paths::CylinderRefinement).
  void SetCylinderRefinement(paths::CylinderRefinement refinement) {
    cylinder_refinement_ = refinement;
  }
  /// Reads the forces of class `from` as class `to` in every later Parse (OpenSim's
  /// Object::renameType; OpenSim's own forward tests read Thelen2003Muscle as
  /// Thelen2003Muscle_Deprecated). The Report lists them under `to`.
  void RenameForceClass(const std::string& from, const std::string& to) {
    force_class_renames_.emplace_back(from, to);
  }

  /// Reads `filename` and adds its bodies, joints and actuators to `system` (which must not be
  /// finalized yet; call system.Finalize() before simulating). Throws sinew::Error.
  void Parse(engine::System& system, const std::string& filename);
  /// As Parse(system, filename), from a spec already read (e.g. one whose defaults were set
  /// from an initial-states file).
  void ParseSpec(engine::System& system, model::ModelSpec spec);
  /// Creates a system (gravity from the file), parses `filename` into it, finalizes it and
  /// returns it; the caller owns it.
  std::unique_ptr<engine::System> Parse(const std::string& filename,
                                        ContactMethod method = ContactMethod::kNsc);

  /// Sets the excitation of the actuator named `actuator_name` (its name in the file, or its
  /// Report key for a repeated name). Call after Parse. Throws sinew::Error for an unknown name.
  /// The System is not changed: the excitations live in the controller GetController returns.
  void SetExcitationFunction(const std::string& actuator_name, functions::FunctionPtr excitation);
  /// The controller that sets the actuators' excitations (engine::State::inputs) from time:
  /// the model's PrescribedControllers, ActivateActuators, the controls file and
  /// SetExcitationFunction, in that order of precedence. Give it to the integrator
  /// (Integrator::SetController) or the Simulation. A later SetExcitationFunction makes a new
  /// controller; the one returned here never changes.
  std::shared_ptr<const forces::ExcitationController> GetController() const { return controller_; }

  /// What the last Parse built.
  const Report& GetReport() const { return report_; }
  /// The model description of the last parsed file.
  const model::ModelSpec& GetSpec() const { return spec_; }
  /// The collision shapes of the last Parse (empty unless EnableCollision was called).
  const contact::CollisionModel& GetCollisionModel() const { return collision_; }
  /// The visual assets of the last Parse, one entry per spec body (no parts with NONE).
  /// A mesh that cannot be found is a Report warning and its body gets primitives.
  const viz::VisualScene& GetVisualScene() const { return scene_; }
  /// The contact method (SetContactMethod or Parse(filename, method); NSC otherwise).
  ContactMethod GetContactMethod() const { return contact_method_; }
  /// Whether EnableCollision was called: the seed's collision shapes collide.
  bool IsCollisionEnabled() const { return collision_enabled_; }

 private:
  void BuildConstraints(engine::System& system, const std::vector<int>& body_map,
                        const std::vector<int>& coordinate_map);
  void BuildForces(engine::System& system, const std::vector<int>& body_map,
                   const std::vector<int>& coordinate_map);
  // Builds one force (of the model, or of `external_loads`) and reports it.
  void BuildOneForce(engine::System& system, const model::ForceSpec& force,
                     const std::vector<int>& body_map, const std::vector<int>& coordinate_map,
                     const io::ExternalLoads* external_loads);
  // Fails for a name given to DisableForce that no force has.
  void CheckDisabledNames() const;
  void AssignExcitations();
  void CheckStrict() const;

  VisType vis_type_ = VisType::kNone;
  bool collision_enabled_ = false;
  CollisionSettings collision_settings_;
  bool verbose_ = false;
  bool activate_actuators_ = false;
  bool strict_ = false;
  std::string controls_file_;
  std::vector<std::string> external_loads_files_;
  std::vector<std::string> disabled_forces_;
  bool equilibrate_muscles_ = false;
  paths::CylinderRefinement cylinder_refinement_ = paths::CylinderRefinement::kSeveralWraps;
  std::vector<std::pair<std::string, std::string>> force_class_renames_;
  std::vector<std::string> geometry_dirs_;
  ContactMethod contact_method_ = ContactMethod::kNsc;
  engine::NscSettings nsc_settings_;

  model::ModelSpec spec_;
  Report report_;
  contact::CollisionModel collision_;
  viz::VisualScene scene_;
  std::shared_ptr<forces::ExcitationController> controller_ =
      std::make_shared<forces::ExcitationController>();
};

}  // namespace sinew::opensim

// The seed's public names, in namespace sinew as the seed has them.
namespace sinew {
using opensim::ContactMethod;
using opensim::OpenSimParser;
using opensim::VisType;
}  // namespace sinew

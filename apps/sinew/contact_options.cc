#include "apps/sinew/contact_options.h"

#include <string>

#include "apps/sinew/notices.h"
#include "apps/sinew/option_checks.h"

namespace sinew::cli {

void AddContactOptions(CLI::App* cmd, ContactOptions& o) {
  cmd->add_flag("--collision", o.collision,
                "The seed's collision shapes (a cylinder per segment, the model's ContactSphere, "
                "ContactHalfSpace, ContactCylinder, ContactEllipsoid and ContactMesh) collide; "
                "never a body with its parent");
  cmd->add_option("--contact", o.method,
                  "With --collision: smc (penalty, default) or nsc (complementarity, fixed "
                  "--step); either's contacts go to contacts.sto (smc_contact.*, nsc_contact.*)")
      ->check(CLI::IsMember({"nsc", "smc"}));
  cmd->add_option("--ground-plane", o.ground_plane,
                  "With --collision: a ground plane y = HEIGHT (m), the solid below it")
      ->check(FiniteNumber());
  // The default contact material, one option per field.
  struct MaterialOption {
    const char* name;
    double* value;
    const char* help;
  };
  contact::CollisionMaterial& m = o.material;
  for (const MaterialOption& option :
       {MaterialOption{"--friction", &m.friction, "Contact friction coefficient (0.6)"},
        {"--restitution", &m.restitution, "Contact restitution (0.4)"},
        {"--young-modulus", &m.young_modulus, "Contact Young's modulus (Pa, 1e7)"},
        {"--poisson-ratio", &m.poisson_ratio, "Contact Poisson ratio (0.3)"},
        {"--kn", &m.kn, "SMC normal stiffness (Pa; 0: from the modulus)"},
        {"--gn", &m.gn, "SMC normal damping (1/(m s), with --kn)"},
        {"--kt", &m.kt,
         "SMC tangential stiffness (Pa; > 0: friction is a spring on each contact's "
         "displacement, capped at u f_n)"},
        {"--gt", &m.gt,
         "SMC friction slope at zero slip (N s/m; with --kt the spring's damping)"}}) {
    cmd->add_option(option.name, *option.value, option.help)->check(FiniteNumber());
  }
  cmd->add_option("--slip-speed", o.slip_speed,
                  "SMC friction regularization speed (m/s, default 1e-3)")
      ->check(FiniteNumber(0.0, true));
  // NSC's stepper; the help shows the library's defaults.
  const engine::NscSettings d;
  cmd->add_option("--nsc-solver", o.nsc_solver,
                  std::string("With --contact nsc: the contact impulse solver, apgd (accelerated "
                              "projected gradient) or gauss-seidel (projected); default ") +
                      engine::ContactSolverMethodName(d.solver.method))
      ->check(CLI::IsMember(
          {engine::ContactSolverMethodName(engine::ContactSolverMethod::kApgd),
           engine::ContactSolverMethodName(engine::ContactSolverMethod::kGaussSeidel)}));
  cmd->add_option("--nsc-iterations", o.nsc_iterations,
                  "With --contact nsc: the most iterations (apgd) or sweeps (gauss-seidel) of "
                  "one step's impulse solve (default " +
                      std::to_string(d.solver.max_iterations) +
                      "); steps that stop there above the tolerance are reported")
      ->check(WholeNumber(1));
  cmd->add_option("--nsc-tolerance", o.nsc_tolerance,
                  "With --contact nsc: the impulse solve stops when the contact law's largest "
                  "violation is at most this (m/s, default " +
                      ShowNumber(d.solver.tolerance) + ")")
      ->check(FiniteNumber(0.0, true));
  cmd->add_option("--nsc-max-recovery-speed", o.nsc_max_recovery_speed,
                  "With --contact nsc: the fastest an overlap is pushed out (m/s, default " +
                      ShowNumber(d.max_recovery_speed) + ")")
      ->check(FiniteNumber(0.0));
  cmd->add_option("--nsc-min-bounce-speed", o.nsc_min_bounce_speed,
                  "With --contact nsc: restitution acts on contacts approaching faster than "
                  "this (m/s, default " +
                      ShowNumber(d.min_bounce_speed) + ")")
      ->check(FiniteNumber(0.0));
}

void ApplyContactOptions(const ContactOptions& o, opensim::OpenSimParser& parser) {
  // The first NSC option given, if any: they need --collision --contact nsc.
  const char* nsc_option = o.nsc_solver               ? "--nsc-solver"
                           : o.nsc_iterations         ? "--nsc-iterations"
                           : o.nsc_tolerance          ? "--nsc-tolerance"
                           : o.nsc_max_recovery_speed ? "--nsc-max-recovery-speed"
                           : o.nsc_min_bounce_speed   ? "--nsc-min-bounce-speed"
                                                      : nullptr;
  if (nsc_option && (!o.collision || o.method != "nsc")) {
    throw Error(
        {}, nsc_option,
        std::string("sets NSC's stepper: it needs --collision --contact nsc") +
            (o.collision ? " (SMC contact, the default, is a force: no impulse solver)" : ""));
  }
  if (!o.collision) {
    const contact::CollisionMaterial d;
    const contact::CollisionMaterial& m = o.material;
    const bool material_set = m.friction != d.friction || m.restitution != d.restitution ||
                              m.young_modulus != d.young_modulus ||
                              m.poisson_ratio != d.poisson_ratio || m.kn != d.kn || m.gn != d.gn ||
                              m.kt != d.kt || m.gt != d.gt;
    const char* option = !o.method.empty() ? "--contact"
                         : o.ground_plane  ? "--ground-plane"
                         : material_set    ? "a contact material option"
                                           : nullptr;
    if (option) throw Error({}, option, "needs --collision");
    return;
  }
  contact::CheckMaterial(o.material, {}, "contact material options");
  parser.EnableCollision();
  parser.SetContactMethod(o.method == "nsc" ? opensim::ContactMethod::kNsc
                                            : opensim::ContactMethod::kSmc);
  if (o.ground_plane) parser.SetGroundPlane(*o.ground_plane);
  parser.SetContactMaterial(o.material);
  parser.SetFrictionSlipSpeed(o.slip_speed);
  if (o.method == "nsc") {
    engine::NscSettings nsc;
    // The option's check admits only the methods' names.
    if (o.nsc_solver) nsc.solver.method = *engine::FindContactSolverMethod(*o.nsc_solver);
    nsc.solver.max_iterations = o.nsc_iterations.value_or(nsc.solver.max_iterations);
    nsc.solver.tolerance = o.nsc_tolerance.value_or(nsc.solver.tolerance);
    nsc.max_recovery_speed = o.nsc_max_recovery_speed.value_or(nsc.max_recovery_speed);
    nsc.min_bounce_speed = o.nsc_min_bounce_speed.value_or(nsc.min_bounce_speed);
    parser.SetNscSettings(nsc);
  }
}

}  // namespace sinew::cli

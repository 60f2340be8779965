#include "apps/sinew/contact_options.h"

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
        {"--kt", &m.kt, "SMC tangential stiffness (not used: a warning)"},
        {"--gt", &m.gt, "SMC friction slope at zero slip (N s/m)"}}) {
    cmd->add_option(option.name, *option.value, option.help)->check(FiniteNumber());
  }
  cmd->add_option("--slip-speed", o.slip_speed,
                  "SMC friction regularization speed (m/s, default 1e-3)")
      ->check(FiniteNumber(0.0, true));
}

void ApplyContactOptions(const ContactOptions& o, opensim::OpenSimParser& parser) {
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
}

}  // namespace sinew::cli

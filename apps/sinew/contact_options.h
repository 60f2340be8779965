// The contact options `simulate` takes: --collision (the seed's collision shapes collide),
// --contact nsc|smc (how: default smc), --ground-plane HEIGHT, the default contact material
// (--friction, --restitution, --young-modulus, --poisson-ratio, --kn, --gn, --kt, --gt) and
// --slip-speed. Without --collision the model's own contact forces still act, nothing else
// collides.
#pragma once

#include <sinew/contact/collision_material.h>
#include <sinew/engine/integrator.h>
#include <sinew/opensim/parser.h>

#include <CLI/CLI.hpp>
#include <memory>
#include <optional>
#include <string>

namespace sinew::cli {

struct ContactOptions {
  bool collision = false;
  std::string method;  ///< "nsc", "smc" or "" (smc when --collision is given)
  std::optional<double> ground_plane;
  contact::CollisionMaterial material;
  double slip_speed = 1e-3;
};

/// Adds the options above to `cmd`, into `options`.
void AddContactOptions(CLI::App* cmd, ContactOptions& options);

/// Checks the options (a contact option without --collision is an error) and sets them on
/// `parser` before it parses.
void ApplyContactOptions(const ContactOptions& options, opensim::OpenSimParser& parser);

/// True when the run needs the NSC time stepper (--collision with --contact nsc).
bool UsesNscContact(const ContactOptions& options);

/// The fixed step of an NSC run when --step is not given (s), the seed's.
inline constexpr double kDefaultNscStep = 1e-3;

/// The integrator of an NSC contact run (--collision --contact nsc): engine::NscIntegrator at
/// `settings.step` (kDefaultNscStep when not > 0) over the parser's collision model, the ground
/// plane queried by the provider itself, the default material's friction and restitution.
std::unique_ptr<engine::Integrator> MakeNscContactIntegrator(
    const engine::System& system, const opensim::OpenSimParser& parser,
    const engine::IntegratorSettings& settings);

}  // namespace sinew::cli

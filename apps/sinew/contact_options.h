// The contact options `simulate` takes: --collision (the seed's collision shapes collide),
// --contact nsc|smc (how: default smc), --ground-plane HEIGHT, the default contact material
// (--friction, --restitution, --young-modulus, --poisson-ratio, --kn, --gn, --kt, --gt) and
// --slip-speed, and with --contact nsc the settings of NSC's stepper (--nsc-solver,
// --nsc-iterations, --nsc-tolerance, --nsc-max-recovery-speed, --nsc-min-bounce-speed).
// Without --collision the model's own contact forces still act, nothing else collides.
#pragma once

#include <sinew/contact/collision_material.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/nsc_integrator.h>
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
  /// NSC's stepper: those not given keep engine::NscSettings' defaults.
  std::optional<std::string> nsc_solver;  ///< "apgd" or "gauss-seidel"
  std::optional<int> nsc_iterations;
  std::optional<double> nsc_tolerance;           ///< m/s
  std::optional<double> nsc_max_recovery_speed;  ///< m/s
  std::optional<double> nsc_min_bounce_speed;    ///< m/s
};

/// Adds the options above to `cmd`, into `options`.
void AddContactOptions(CLI::App* cmd, ContactOptions& options);

/// Checks the options (a contact option without --collision, or an NSC option without
/// --contact nsc, is an error) and sets them on `parser` before it parses.
void ApplyContactOptions(const ContactOptions& options, opensim::OpenSimParser& parser);

}  // namespace sinew::cli

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

}  // namespace sinew::cli

// The contacts table of an NSC run (`sinew simulate --collision --contact nsc --out DIR` writes
// DIR/contacts.sto): the contact impulses of the stepper's last step divided by its length, in
// the layout of SMC's collision rows (contact_table.h): per body with a collision shape, the
// force and torque on it; the number of active contacts, in all and per body pair; and what the
// impulse solver did: the last step's iterations and final residual, and the steps so far whose
// solve stopped above the tolerance.
#pragma once

#include <sinew/contact/collision_contact_provider.h>
#include <sinew/engine/nsc_integrator.h>
#include <sinew/engine/system.h>

#include <string>
#include <utility>
#include <vector>

namespace sinew::contact {

/// The name NSC's columns start with, as SMC's start with its force element's "smc_contact".
inline constexpr const char* kNscTableName = "nsc_contact";

class NscContactTable {
 public:
  /// Columns for the bodies and body pairs `provider` tests (its shapes' bodies, ground
  /// included). `integrator` must be the stepper that uses `provider`; both, and `system`,
  /// must outlive the table.
  NscContactTable(const engine::System& system, const engine::NscIntegrator& integrator,
                  const CollisionContactProvider& provider);

  /// "nsc_contact.<body>.force.X|Y|Z" and ".torque.X|Y|Z" per body (N, and N m about the
  /// body's origin, in G), "nsc_contact.active_contacts", then per body pair
  /// "nsc_contact.<body1>-<body2>.active_contacts", then "nsc_contact.solver_iterations",
  /// "nsc_contact.solver_residual" and "nsc_contact.unconverged_steps".
  const std::vector<std::string>& labels() const { return labels_; }

  /// The bodies with columns, in labels() order (engine body indices, 0 = ground): the body of
  /// column group "nsc_contact.<name of bodies()[i]>".
  const std::vector<int>& bodies() const { return bodies_; }

  /// The values of the integrator's last step in labels() order (`row` is resized): its
  /// contact impulses divided by its length, the contacts whose normal impulse is > 0, its
  /// impulse solve's iterations and final residual (m/s; both 0 without contacts), and the
  /// steps since the start whose solve ended above the tolerance (engine::NscSolveSummary:
  /// the difference between two rows counts those between them). Zero before the first step.
  void Row(std::vector<double>& row) const;

 private:
  const engine::NscIntegrator& integrator_;
  std::vector<int> bodies_;
  std::vector<std::pair<int, int>> pairs_;
  std::vector<std::string> labels_;
  mutable std::vector<engine::BodyContactImpulse> impulses_;
};

}  // namespace sinew::contact

// OpenSim's HuntCrossleyForce (Simbody's HuntCrossleyForce): Hertz contact with Hunt-Crossley
// dissipation and regularized Coulomb friction between every pair of its shapes on different
// bodies (a sphere with a half-space or another sphere). docs/contact.md gives the formulas.
#pragma once

#include <sinew/contact/contact_force.h>
#include <sinew/contact/contact_shape.h>

#include <string>
#include <utility>
#include <vector>

namespace sinew::contact {

/// Hunt-Crossley contact. For a contact of depth d and effective radius R between shapes with
/// materials 1 and 2 (k_i' = stiffness_i^(2/3), s = k_2' / (k_1' + k_2')): k = k_1' s,
/// c = c_1 s + c_2 (1 - s), Hertz force f_H = 4/3 k d sqrt(R k d), normal force
/// f = f_H (1 + 3/2 c v_n) (v_n the approach speed; no force when f <= 0), friction
/// FrictionForce(f, v_slip, ...) with each friction coefficient combined as 2 u1 u2 / (u1 + u2).
/// Potential energy 2/5 f_H d per contact.
class HuntCrossleyForce final : public ContactForce {
 public:
  /// `shapes` with their `materials` (same length). Only sphere/half-space and sphere/sphere
  /// pairs on different bodies make contacts; shapes of other kinds must not be given.
  HuntCrossleyForce(std::string name, std::vector<ContactShape> shapes,
                    std::vector<ContactMaterial> materials, double transition_velocity,
                    std::vector<RecordGroup> groups);

  double VisitContacts(const engine::State& state, ContactSink& sink) const override;

 private:
  std::vector<ContactShape> shapes_;
  std::vector<ContactMaterial> materials_;
  std::vector<std::pair<int, int>> pairs_;  ///< (shape 1, shape 2), half-space first
  double transition_velocity_;
};

}  // namespace sinew::contact

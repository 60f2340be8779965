// SMC, the seed's smooth (penalty) contact method, as a force element over the contacts of a
// CollisionDetector: Hertz normal force with restitution through its damping, regularized
// Coulomb friction. docs/contact.md gives the laws.
#pragma once

#include <sinew/contact/collision_detection.h>
#include <sinew/contact/contact_force.h>

#include <memory>
#include <string>
#include <vector>

namespace sinew::contact {

/// Smooth contact between collision shapes. For a contact of depth d, effective radius R,
/// effective mass m = m1 m2 / (m1 + m2) (ground's mass infinite), approach speed v_n and slip
/// velocity v_t, with the pair's material:
/// - kn > 0: f_n = sqrt(R d) (kn d + gn m v_n);
/// - otherwise Hertz from the effective modulus E*: f_n = 4/3 E* sqrt(R d) d + c v_n with
///   c = 2 sqrt(5/6) b sqrt(2 E* sqrt(R d) m), b = -ln(e) / sqrt(ln(e)^2 + pi^2) (restitution e);
/// f_n is never negative; friction -u f_n v_t / sqrt(|v_t|^2 + v_s^2) with the slip speed
/// v_s = `slip_speed`, or u f_n / gt when gt > 0 (so gt is the slope at zero slip).
/// Potential energy: the Hertz elastic part, 2/5 f_el d per contact.
class SmoothCollisionForce final : public ContactForce {
 public:
  /// `detector`'s bodies are engine body indices; `masses` per engine body (ground first,
  /// its entry ignored); `groups` the bodies reported; `pairs` the body pairs whose active
  /// contacts are counted (labels "<body1>-<body2>").
  SmoothCollisionForce(std::string name, std::shared_ptr<const CollisionDetector> detector,
                       std::vector<double> masses, double slip_speed,
                       std::vector<RecordGroup> groups, std::vector<PairGroup> pairs);

  double VisitContacts(const engine::State& state, ContactSink& sink) const override;
  double slip_speed() const { return slip_speed_; }

 private:
  // One contact's force into `sink`; returns its elastic energy.
  double ApplyContact(const engine::State& state, const CollisionContact& c,
                      ContactSink& sink) const;

  std::shared_ptr<const CollisionDetector> detector_;
  std::vector<double> masses_;
  double slip_speed_;
};

}  // namespace sinew::contact

// OpenSim's SmoothSphereHalfSpaceForce (Simbody's SmoothSphereHalfSpaceForce): a Hunt-Crossley
// contact between one sphere and one half-space whose switches are smoothed (tanh and square
// roots), so that the force is differentiable everywhere, for optimal control.
#pragma once

#include <sinew/contact/contact_force.h>
#include <sinew/contact/contact_shape.h>

#include <string>

namespace sinew::contact {

/// The parameters of SmoothSphereHalfSpaceForce, with OpenSim's defaults.
struct SmoothContactParameters {
  double stiffness = 1.0;             ///< Pa (both materials have it)
  double dissipation = 0.0;           ///< s/m
  double static_friction = 0.0;
  double dynamic_friction = 0.0;
  double viscous_friction = 0.0;      ///< s/m
  double transition_velocity = 0.01;  ///< m/s
  double constant_contact_force = 1e-5;   ///< c_f (N^(2/3)/... as Simbody: added under sqrt)
  double hertz_smoothing = 300.0;         ///< b_d (1/m)
  double hunt_crossley_smoothing = 50.0;  ///< b_v (s/m)
};

/// With d the sphere's indentation into the half-space (negative when apart), n the half-space's
/// inward normal (its frame's +x), k = stiffness^(2/3) / 2, v_n the approach speed:
/// f_H = 4/3 k sqrt(R k) (sqrt(d^2 + c_f))^(3/2) (1/2 + 1/2 tanh(b_d d)),
/// f = f_H (1 + 3/2 c v_n) (1/2 + 1/2 tanh(b_v (v_n + 2 / (3 c)))) (the last factor is 1 when
/// c = 0), friction FrictionForce(f, sqrt(|v_t|^2 + c_f), ...) along v_t / sqrt(|v_t|^2 + c_f).
/// The force acts at the sphere's surface point minus half the indentation along n, and never
/// vanishes entirely (c_f): a contact is counted active when d > 0. Potential energy 2/5 f_H d
/// (Simbody's approximation; not the integral of f_H).
class SmoothSphereHalfSpaceForce final : public ContactForce {
 public:
  SmoothSphereHalfSpaceForce(std::string name, ContactShape sphere, ContactShape half_space,
                             const SmoothContactParameters& parameters);

  double VisitContacts(const engine::State& state, ContactSink& sink) const override;

 private:
  ContactShape sphere_, half_space_;
  SmoothContactParameters parameters_;
};

}  // namespace sinew::contact

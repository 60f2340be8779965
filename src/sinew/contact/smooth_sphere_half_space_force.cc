#include <sinew/contact/smooth_sphere_half_space_force.h>
#include <sinew/engine/pose.h>
#include <sinew/engine/state.h>

#include <cmath>
#include <utility>

namespace sinew::contact {

SmoothSphereHalfSpaceForce::SmoothSphereHalfSpaceForce(std::string name, ContactShape sphere,
                                                       ContactShape half_space,
                                                       const SmoothContactParameters& parameters)
    : ContactForce(std::move(name),
                   {{"Sphere", sphere.body}, {"HalfSpace", half_space.body}}),
      sphere_(std::move(sphere)),
      half_space_(std::move(half_space)),
      parameters_(parameters) {}

double SmoothSphereHalfSpaceForce::VisitContacts(const engine::State& state,
                                                 ContactSink& sink) const {
  const SmoothContactParameters& p = parameters_;
  const engine::BodyState& sphere_body = state.bodies[sphere_.body];
  const engine::BodyState& plane_body = state.bodies[half_space_.body];
  // Only the sphere's centre matters (OpenSim passes its location, not its orientation).
  const Vec3 p_GS = engine::PoseOf(sphere_body) * sphere_.X_BC.p;
  const Transform X_GH = engine::PoseOf(plane_body) * half_space_.X_BC;
  const Vec3 n_G = X_GH.R.col(0);  // into the half-space
  const double R = sphere_.radius;
  const double d = (p_GS - X_GH.p).dot(n_G) + R;
  const Vec3 p_G = p_GS + R * n_G - 0.5 * d * n_G;

  const Vec3 v_G =
      engine::PointVelocity(sphere_body, p_G) - engine::PointVelocity(plane_body, p_G);
  const double v_normal = v_G.dot(n_G);
  const Vec3 v_tangent = v_G - v_normal * n_G;

  const double k = 0.5 * std::pow(p.stiffness, 2.0 / 3.0);
  const double f_hertz = 4.0 / 3.0 * k * std::sqrt(R * k) *
                         std::pow(std::sqrt(d * d + p.constant_contact_force), 1.5) *
                         (0.5 + 0.5 * std::tanh(p.hertz_smoothing * d));
  const double c = p.dissipation;
  const double switch_on =
      c != 0.0 ? 0.5 + 0.5 * std::tanh(p.hunt_crossley_smoothing * (v_normal + 2.0 / (3.0 * c)))
               : 1.0;
  const double f = f_hertz * (1.0 + 1.5 * c * v_normal) * switch_on;
  const double v_slip = std::sqrt(v_tangent.squaredNorm() + p.constant_contact_force);
  const double friction = FrictionForce(f, v_slip, p.static_friction, p.dynamic_friction,
                                        p.viscous_friction, p.transition_velocity);
  const Vec3 f_G = f * n_G + friction * v_tangent / v_slip;
  // The half-space (body 2 of the load) gets f_G, the sphere its opposite.
  sink.Add({sphere_.body, half_space_.body, p_G, f_G, d > 0.0});
  return 2.0 / 5.0 * f_hertz * d;
}

}  // namespace sinew::contact

#include <sinew/contact/hunt_crossley_force.h>
#include <sinew/contact/point_contact.h>
#include <sinew/engine/pose.h>
#include <sinew/engine/state.h>

#include <cmath>
#include <utility>

namespace sinew::contact {
namespace {

// Simbody's combination of two friction coefficients: 2 u1 u2 / (u1 + u2), 0 when both are 0.
double CombineFriction(double u1, double u2) {
  return (u1 != 0.0 || u2 != 0.0) ? 2.0 * u1 * u2 / (u1 + u2) : 0.0;
}

}  // namespace

HuntCrossleyForce::HuntCrossleyForce(std::string name, std::vector<ContactShape> shapes,
                                     std::vector<ContactMaterial> materials,
                                     double transition_velocity, std::vector<RecordGroup> groups)
    : ContactForce(std::move(name), std::move(groups)),
      shapes_(std::move(shapes)),
      materials_(std::move(materials)),
      transition_velocity_(transition_velocity) {
  for (int i = 0; i < static_cast<int>(shapes_.size()); ++i) {
    for (int j = i + 1; j < static_cast<int>(shapes_.size()); ++j) {
      if (shapes_[i].body == shapes_[j].body) continue;
      if (IsPointContactPair(shapes_[i].kind, shapes_[j].kind)) pairs_.emplace_back(i, j);
      else if (IsPointContactPair(shapes_[j].kind, shapes_[i].kind)) pairs_.emplace_back(j, i);
    }
  }
}

double HuntCrossleyForce::VisitContacts(const engine::State& state, ContactSink& sink) const {
  double energy = 0.0;
  for (const auto& [i, j] : pairs_) {
    const ContactShape& shape1 = shapes_[i];
    const ContactShape& shape2 = shapes_[j];
    const engine::BodyState& body1 = state.bodies[shape1.body];
    const engine::BodyState& body2 = state.bodies[shape2.body];
    const std::optional<PointContact> contact = FindPointContact(
        shape1, engine::PoseOf(body1) * shape1.X_BC, shape2, engine::PoseOf(body2) * shape2.X_BC);
    if (!contact) continue;
    const ContactMaterial& m1 = materials_[i];
    const ContactMaterial& m2 = materials_[j];
    // Stiffnesses enter as k^(2/3); the contact point moves towards the softer material.
    const double k1 = std::pow(m1.stiffness, 2.0 / 3.0);
    const double k2 = std::pow(m2.stiffness, 2.0 / 3.0);
    if (!(k1 + k2 > 0.0)) continue;
    const double s1 = k2 / (k1 + k2);
    const double d = contact->depth;
    const Vec3& n_G = contact->n_G;
    const Vec3 p_G = contact->p_G + d * (0.5 - s1) * n_G;
    const double k = k1 * s1;
    const double c = m1.dissipation * s1 + m2.dissipation * (1.0 - s1);
    const double f_hertz = 4.0 / 3.0 * k * d * std::sqrt(contact->radius * k * d);
    energy += 2.0 / 5.0 * f_hertz * d;

    // Velocity of body 1's point relative to body 2's at the contact point.
    const Vec3 v_G = engine::PointVelocity(body1, p_G) - engine::PointVelocity(body2, p_G);
    const double v_normal = v_G.dot(n_G);
    const Vec3 v_tangent = v_G - v_normal * n_G;
    const double f = f_hertz * (1.0 + 1.5 * c * v_normal);
    if (f <= 0.0) continue;
    Vec3 f_G = f * n_G;
    const double v_slip = v_tangent.norm();
    if (v_slip != 0.0) {
      const double friction = FrictionForce(
          f, v_slip, CombineFriction(m1.static_friction, m2.static_friction),
          CombineFriction(m1.dynamic_friction, m2.dynamic_friction),
          CombineFriction(m1.viscous_friction, m2.viscous_friction), transition_velocity_);
      f_G += friction * v_tangent / v_slip;
    }
    sink.Add({shape1.body, shape2.body, p_G, f_G});
  }
  return energy;
}

}  // namespace sinew::contact

#include <sinew/contact/contact_shape.h>

#include <algorithm>

namespace sinew::contact {

double FrictionForce(double f_normal, double v_slip, double static_friction,
                     double dynamic_friction, double viscous_friction,
                     double transition_velocity) {
  const double v_r = v_slip / transition_velocity;
  return f_normal * (std::min(v_r, 1.0) * (dynamic_friction + 2.0 *
                                               (static_friction - dynamic_friction) /
                                               (1.0 + v_r * v_r)) +
                     viscous_friction * v_slip);
}

}  // namespace sinew::contact

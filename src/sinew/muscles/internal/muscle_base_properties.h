// The properties every OpenSim Muscle has (Muscle.h), read the same way for each muscle class.
#pragma once

#include <sinew/model/element_values.h>

namespace sinew::muscles::internal {

/// Reads max_isometric_force, optimal_fiber_length, tendon_slack_length,
/// pennation_angle_at_optimal, max_contraction_velocity, ignore_tendon_compliance and
/// ignore_activation_dynamics into `p` (any parameters struct with those members), keeping its
/// values (the class's defaults) for absent properties.
template <typename Parameters>
void ReadMuscleBaseProperties(const model::ElementValues& v, Parameters* p) {
  p->max_isometric_force = v.Double("max_isometric_force", p->max_isometric_force);
  p->optimal_fiber_length = v.Double("optimal_fiber_length", p->optimal_fiber_length);
  p->tendon_slack_length = v.Double("tendon_slack_length", p->tendon_slack_length);
  p->pennation_angle_at_optimal =
      v.Double("pennation_angle_at_optimal", p->pennation_angle_at_optimal);
  p->max_contraction_velocity = v.Double("max_contraction_velocity", p->max_contraction_velocity);
  p->ignore_tendon_compliance = v.Bool("ignore_tendon_compliance", p->ignore_tendon_compliance);
  p->ignore_activation_dynamics =
      v.Bool("ignore_activation_dynamics", p->ignore_activation_dynamics);
}

}  // namespace sinew::muscles::internal

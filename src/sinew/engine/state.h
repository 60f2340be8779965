// The changing data of a simulation: time, body poses and twists, joint coordinates and speeds,
// auxiliary state variables z, and the inputs (controls) an evaluation reads.
// A State is a plain value: copy it to save it, assign it back to restore it.
#pragma once

#include <sinew/engine/body.h>
#include <sinew/math/types.h>

#include <memory>
#include <vector>

namespace sinew::engine {

class ForceElement;

/// What a force element carries from one accepted step to the next (a contact history):
/// immutable once made, so copies of a State share it; an update replaces it.
struct DiscreteData {
  virtual ~DiscreteData() = default;
};

/// A force element's DiscreteData in a State.
struct DiscreteDataEntry {
  const ForceElement* owner = nullptr;
  std::shared_ptr<const DiscreteData> data;
};

/// Everything that changes during a simulation of a System.
struct State {
  double t = 0.0;                 ///< time (s)
  std::vector<BodyState> bodies;  ///< one per System body; bodies[0] (ground) stays at rest
  /// Every coordinate q (rad or m) and speed u (rad/s or m/s), in System coordinate order.
  /// Coordinates of parameterized joints are integrated unknowns; those of direct Cartesian
  /// joints are read off the body poses after every step (see UpdateDirectCoordinates).
  VecX q;
  VecX u;
  /// Auxiliary continuous state variables (muscle activations, fiber lengths, ...), declared by
  /// force elements and laid out by System::Finalize (names: System::state_variable_names()).
  /// Integrated with q and u, under the same error control.
  VecX z;
  /// Inputs (controls, excitations) read by every evaluation, declared by force elements
  /// (names: System::input_names()). They hold their value during a step unless a Controller
  /// given to the integrator sets them from time and state at every evaluation.
  VecX inputs;
  /// Data force elements carry between steps (ForceElement::UpdateDiscreteData), at most one
  /// entry per element; empty until the first accepted step. Evaluations read it, only the
  /// integrators' step ends (System::UpdateDiscreteData) change it.
  std::vector<DiscreteDataEntry> discrete;
};

/// The data `owner` keeps in `state`, or null.
inline const DiscreteData* FindDiscreteData(const State& state, const ForceElement* owner) {
  for (const DiscreteDataEntry& entry : state.discrete) {
    if (entry.owner == owner) return entry.data.get();
  }
  return nullptr;
}

}  // namespace sinew::engine

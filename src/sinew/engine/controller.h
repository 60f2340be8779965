// The Controller interface: sets a System's inputs (controls, excitations) from time and state
// at every evaluation. Controllers live outside the System, so one finalized System can be
// simulated by many threads with different controls.
#pragma once

#include <sinew/math/types.h>

namespace sinew::engine {

class System;
struct State;

/// Sets inputs from time and state. Const and free of hidden state, so that one controller may
/// serve several integrators at once.
class Controller {
 public:
  virtual ~Controller() = default;
  /// Writes the inputs this controller drives into `inputs` (System::num_inputs() entries, on
  /// entry the state's own values); leaves the others unchanged.
  virtual void CalcInputs(const System& system, const State& state,
                          Eigen::Ref<VecX> inputs) const = 0;
};

}  // namespace sinew::engine

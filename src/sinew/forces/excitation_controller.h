// ExcitationController: inputs driven by functions of time (the seed's excitation functions,
// OpenSim's PrescribedController and ControlSet files). It lives outside the System; the
// OpenSim parser builds one, and a new one replaces it when an excitation changes, so a
// controller in use by a running simulation never changes under it.
#pragma once

#include <sinew/engine/controller.h>
#include <sinew/functions/function.h>

#include <vector>

namespace sinew::forces {

/// Sets each input it knows to e(t) from that input's function.
class ExcitationController final : public engine::Controller {
 public:
  /// Drives input `input` (an index into State::inputs) with `excitation`; null stops driving
  /// it (the state's own value is then used).
  void Set(int input, functions::FunctionPtr excitation);
  /// The function driving `input`, or null.
  functions::FunctionPtr Get(int input) const;
  /// e(t) of `input` at time t (0 when no function drives it).
  double Calc(int input, double t) const;

  void CalcInputs(const engine::System& system, const engine::State& state,
                  Eigen::Ref<VecX> inputs) const override;

 private:
  struct Entry {
    int input;
    functions::FunctionPtr excitation;
  };
  std::vector<Entry> entries_;  // sorted by input
};

}  // namespace sinew::forces

#include <sinew/common/error.h>
#include <sinew/engine/state.h>
#include <sinew/forces/excitation_controller.h>

#include <algorithm>
#include <string>

namespace sinew::forces {

void ExcitationController::Set(int input, functions::FunctionPtr excitation) {
  if (input < 0) throw Error("ExcitationController: input index " + std::to_string(input));
  auto it = std::lower_bound(entries_.begin(), entries_.end(), input,
                             [](const Entry& e, int i) { return e.input < i; });
  if (it != entries_.end() && it->input == input) {
    if (excitation) {
      it->excitation = std::move(excitation);
    } else {
      entries_.erase(it);
    }
  } else if (excitation) {
    entries_.insert(it, Entry{input, std::move(excitation)});
  }
}

functions::FunctionPtr ExcitationController::Get(int input) const {
  for (const Entry& e : entries_) {
    if (e.input == input) return e.excitation;
  }
  return nullptr;
}

double ExcitationController::Calc(int input, double t) const {
  const functions::FunctionPtr f = Get(input);
  return f ? f->Calc(t) : 0.0;
}

void ExcitationController::CalcInputs(const engine::System&, const engine::State& state,
                                      Eigen::Ref<VecX> inputs) const {
  for (const Entry& e : entries_) {
    if (e.input < inputs.size()) inputs[e.input] = e.excitation->Calc(state.t);
  }
}

}  // namespace sinew::forces

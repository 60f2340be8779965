// ForceReporter: what every force element of a system applies, as the columns of OpenSim's
// ForceReporter (the table `sinew simulate` writes to forces.sto). Each element names its own
// columns (ForceElement::RecordLabels) and values (CalcRecordValues).
#pragma once

#include <sinew/engine/state.h>
#include <sinew/engine/system.h>

#include <string>
#include <vector>

namespace sinew::engine {

/// The forces table of a finalized system: one row per reported state. Holds a reference to
/// the system, which must outlive it.
class ForceReporter {
 public:
  /// Collects the labels of every force element of `system`, in element order.
  explicit ForceReporter(const System& system);

  /// Every column label (without time).
  const std::vector<std::string>& labels() const { return labels_; }
  /// The values of every column at `state` (its inputs as the state holds them: a state from
  /// engine::Simulate or an integrator's StepTo holds its controller's inputs), into `row`
  /// (resized to labels().size()). Throws sinew::Error when an element reports a number of
  /// values different from its labels.
  void CalcRow(const State& state, std::vector<double>& row) const;

 private:
  const System& system_;
  std::vector<std::string> labels_;
  std::vector<size_t> counts_;  // columns of each element
};

}  // namespace sinew::engine

// Where a muscle with optional activation dynamics and an optional fiber state keeps them in
// its state variables (OpenSim's ignore_activation_dynamics and ignore_tendon_compliance each
// remove one): the bookkeeping Millard2012 and DeGrooteFregly2016 share.
#pragma once

#include <sinew/math/types.h>

#include <string>
#include <vector>

namespace sinew::muscles {

/// Indices into a muscle's z of "activation" and of its fiber state, -1 when left out.
struct MuscleStateLayout {
  int activation = -1;
  int fiber = -1;

  MuscleStateLayout(bool ignore_activation_dynamics, bool ignore_tendon_compliance) {
    int next = 0;
    if (!ignore_activation_dynamics) activation = next++;
    if (!ignore_tendon_compliance) fiber = next++;
  }
  /// "activation" and `fiber_name`, those kept.
  std::vector<std::string> Names(const std::string& fiber_name) const {
    std::vector<std::string> names;
    if (activation >= 0) names.push_back("activation");
    if (fiber >= 0) names.push_back(fiber_name);
    return names;
  }
  /// The activation state, or `otherwise` (the excitation, or a default) without one.
  double Activation(Eigen::Ref<const VecX> z, double otherwise) const {
    return activation >= 0 ? z[activation] : otherwise;
  }
  /// The fiber state, or `otherwise` without one.
  double Fiber(Eigen::Ref<const VecX> z, double otherwise) const {
    return fiber >= 0 ? z[fiber] : otherwise;
  }
};

}  // namespace sinew::muscles

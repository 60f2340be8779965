// The reference for KktSolver::SolveUnitLoadResponses: six full KktSolver::Solve per source
// body, one per unit load on its twist columns, read at the targets' twists.
#pragma once

#include <sinew/engine/kkt.h>

#include <algorithm>
#include <limits>
#include <vector>

namespace sinew::engine::testing {

/// The largest difference between SolveUnitLoadResponses(source, targets) and the targets'
/// twists in six full solves with unit loads on source's twist columns, relative to the
/// largest such twist entry (the response matrix's scale). `kkt` must be factorized; returns
/// infinity when SolveUnitLoadResponses refuses or the responses are all zero.
inline double UnitLoadResponseError(const KktSolver& kkt, int source,
                                    const std::vector<int>& targets) {
  MatX responses(6 * targets.size(), 6);
  if (!kkt.SolveUnitLoadResponses(source, targets, responses)) {
    return std::numeric_limits<double>::infinity();
  }
  VecX rhs = VecX::Zero(kkt.num_velocities() + kkt.num_equations()), x;
  double largest = 0.0, error = 0.0;
  for (int j = 0; j < 6; ++j) {
    rhs.setZero();
    rhs[kkt.BodyColumn(source) + j] = 1.0;
    kkt.Solve(rhs, x);
    for (size_t t = 0; t < targets.size(); ++t) {
      const VecX expected = x.segment<6>(kkt.BodyColumn(targets[t]));
      largest = std::max(largest, expected.lpNorm<Eigen::Infinity>());
      const auto got = responses.block<6, 1>(6 * static_cast<Eigen::Index>(t), j);
      error = std::max(error, (got - expected).lpNorm<Eigen::Infinity>());
    }
  }
  return largest > 0.0 ? error / largest : std::numeric_limits<double>::infinity();
}

}  // namespace sinew::engine::testing

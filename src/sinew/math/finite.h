// Whether every entry of a vector or matrix is finite, in one vectorizable pass.
#pragma once

#include <Eigen/Core>

namespace sinew {

/// Same answer as Eigen's allFinite() (x - x is 0 for a finite x and NaN for an infinite or NaN
/// one, and a sum of zeros is exactly 0), as one subtraction and one addition per entry that
/// the compiler vectorizes; allFinite()'s per-entry comparisons cost several times more on the
/// engine's long right-hand sides and solutions.
template <typename Derived>
bool AllFinite(const Eigen::DenseBase<Derived>& x) {
  return (x.derived().array() - x.derived().array()).sum() == 0.0;
}

}  // namespace sinew

// JointValues: a joint's coordinates, speeds or rates (at most 6) gathered on the stack, for the
// JointModel calls of every evaluation (no heap use).
#pragma once

#include <sinew/math/types.h>

#include <array>
#include <span>
#include <vector>

namespace sinew::engine {

/// Up to 6 values of one joint, usable wherever a JointModel takes a span.
class JointValues {
 public:
  /// `n` values equal to `value`.
  explicit JointValues(size_t n = 0, double value = 0.0) : n_(n) { values_.fill(value); }
  /// x[i] for each index in `indices` (a joint's coordinate indices).
  JointValues(const VecX& x, const std::vector<int>& indices) : n_(indices.size()) {
    for (size_t i = 0; i < n_; ++i) values_[i] = x[indices[i]];
  }

  size_t size() const { return n_; }
  double& operator[](size_t i) { return values_[i]; }
  double operator[](size_t i) const { return values_[i]; }
  operator std::span<const double>() const { return {values_.data(), n_}; }
  operator std::span<double>() { return {values_.data(), n_}; }
  const double* begin() const { return values_.data(); }
  const double* end() const { return values_.data() + n_; }

 private:
  std::array<double, 6> values_{};
  size_t n_;
};

}  // namespace sinew::engine

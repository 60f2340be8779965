// Checks shared by the wrap surface tests: properties every surface must have whatever its
// shape (P <-> S reversibility, continuity where the wrap engages) and a side-of-axis check.
#pragma once

#include <gtest/gtest.h>
#include <sinew/paths/wrap_surface.h>

#include <utility>
#include <vector>

#include "wrap_reference.h"

namespace sinew::paths::testing {

/// Wrapping S to P gives the same path reversed: T1 and T2 swapped (to `tolerance` m) and the
/// same arc length.
inline void ExpectReversible(const WrapSurface& surface,
                             const std::vector<std::pair<Vec3, Vec3>>& pairs,
                             const WrapOptions& options, double tolerance) {
  for (const auto& [p, s] : pairs) {
    const WrapResult forward = surface.Wrap(p, s, options);
    const WrapResult backward = surface.Wrap(s, p, options);
    ASSERT_EQ(backward.wrapped, forward.wrapped);
    EXPECT_LT((forward.p_WT1 - backward.p_WT2).norm(), tolerance);
    EXPECT_LT((forward.p_WT2 - backward.p_WT1).norm(), tolerance);
    EXPECT_NEAR(forward.arc_length, backward.arc_length, tolerance);
  }
}

/// Moves P in `steps` equal steps from `p_from` to `p_to` with S fixed, across the boundary
/// where the wrap engages (some positions must wrap, some not). A path length is 1-Lipschitz in
/// its end point, so no step may change it by more than the step plus `rounding` m; a jump
/// where the wrap engages would break that.
inline void ExpectContinuousAcrossEngagement(const WrapSurface& surface, const Vec3& p_from,
                                             const Vec3& p_to, const Vec3& s, int steps,
                                             double rounding) {
  const WrapOptions options;
  const double step = (p_to - p_from).norm() / steps;
  double previous = 0.0;
  int wrapped = 0;
  for (int i = 0; i <= steps; ++i) {
    const Vec3 p = p_from + (p_to - p_from) * (static_cast<double>(i) / steps);
    const WrapResult result = surface.Wrap(p, s, options);
    wrapped += result.wrapped ? 1 : 0;
    const double length = PathLength(p, s, result);
    if (i > 0) {
      EXPECT_LE(std::abs(length - previous), step + rounding) << "at step " << i;
    }
    previous = length;
  }
  EXPECT_GT(wrapped, 0);
  EXPECT_LT(wrapped, steps + 1);
}

/// `result` wraps round the side of W's `axis` with sign `side` (both tangent points there),
/// is mandatory or not as given, and its path is `length` m long (to 1e-12 m).
inline void ExpectWrapOnSide(const WrapResult& result, const Vec3& p, const Vec3& s, int axis,
                             int side, bool mandatory, double length) {
  ASSERT_TRUE(result.wrapped);
  EXPECT_EQ(result.mandatory, mandatory);
  EXPECT_GT(side * result.p_WT1[axis], 0.0);
  EXPECT_GT(side * result.p_WT2[axis], 0.0);
  EXPECT_NEAR(PathLength(p, s, result), length, 1e-12);
}

}  // namespace sinew::paths::testing

// OpenSim's obstacle-set wraps against closed forms. WrapCylinderObst: in the cross-section,
// the path turns round a circle of 0.8 times the radius the way `wrapDirection` says, and wraps
// only when that turn is 0 to 180 degrees; Q's and T's heights are where the unrolled path
// (a straight line) meets them, and the arc's length is the circle's (the rise left out, as
// OpenSim does). WrapSphereObst: the great-circle path over a sphere of 0.8 times the radius,
// when the segment enters that sphere.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/paths/obstacle_arc.h>
#include <sinew/paths/wrap_cylinder_obst.h>
#include <sinew/paths/wrap_sphere_obst.h>

#include <cmath>
#include <numbers>

#include "wrap_checks.h"
#include "wrap_reference.h"

namespace sinew::paths {
namespace {

using testing::CircleWrapLength;
using testing::PathLength;

constexpr double kPi = std::numbers::pi;
constexpr double kRadius = 0.02;                               // the obstacle's `radius` (m)
constexpr double kCircle = kObstacleRadiusFraction * kRadius;  // what the path wraps over
const WrapOptions kOptions{WrapOptions::Method::kHybrid, true, true, {}};

// The cross-section path of a cylinder obstacle, from the geometry alone: P and S at polar
// angles and distances; the turn from P's tangent point to S's, `turn` (+1 counter-clockwise
// about z, -1 clockwise), is the angle from P to S that way less acos(r / d) at each end.
struct CrossSection {
  bool wraps;
  double straight_p, straight_s, arc;  // |P - Q|, |T - S| and the arc in the cross-section
};
CrossSection ExpectedCrossSection(const Vec3& p, const Vec3& s, int turn) {
  const double dp = std::hypot(p.x(), p.y()), ds = std::hypot(s.x(), s.y());
  double between = turn * (std::atan2(s.y(), s.x()) - std::atan2(p.y(), p.x()));
  between = std::fmod(between + 4 * kPi, 2 * kPi);
  const double angle = between - std::acos(kCircle / dp) - std::acos(kCircle / ds);
  return {angle >= 0.0 && angle <= kPi, std::sqrt(dp * dp - kCircle * kCircle),
          std::sqrt(ds * ds - kCircle * kCircle), kCircle * angle};
}

// Random P and S outside the circle, at most `rise` apart in height (at one height with
// `same_height`).
std::vector<std::pair<Vec3, Vec3>> OutsidePairs(int count, unsigned seed, double rise,
                                                bool same_height) {
  return testing::RandomPairs(count, 0.08, seed, same_height, [&](const Vec3& p, const Vec3& s) {
    return std::hypot(p.x(), p.y()) > 1.05 * kCircle && std::hypot(s.x(), s.y()) > 1.05 * kCircle &&
           std::abs(s.z() - p.z()) <= rise;
  });
}

TEST(WrapCylinderObstTest, SameHeightPathsAreTheCircleArcTheWrapDirectionTurns) {
  int wrapped = 0, straight = 0;
  for (const auto direction :
       {WrapCylinderObst::Direction::kRightHand, WrapCylinderObst::Direction::kLeftHand}) {
    const WrapCylinderObst obstacle(kRadius, direction);
    const int turn = direction == WrapCylinderObst::Direction::kRightHand ? 1 : -1;
    for (const auto& [p, s] : OutsidePairs(2000, 5, 0.0, true)) {
      const CrossSection expected = ExpectedCrossSection(p, s, turn);
      const WrapResult result = obstacle.Wrap(p, s, kOptions);
      ASSERT_EQ(result.wrapped, expected.wraps) << p.transpose() << " | " << s.transpose();
      EXPECT_FALSE(result.mandatory);
      if (!expected.wraps) {
        ++straight;
        continue;
      }
      ++wrapped;
      // acos of the chord's cosine near 0 or pi loses digits: 1e-7 rad at worst times r.
      const double length = expected.straight_p + expected.arc + expected.straight_s;
      EXPECT_NEAR(PathLength(p, s, result), length, 1e-9);
      EXPECT_NEAR(std::hypot(result.p_WT1.x(), result.p_WT1.y()), kCircle, 1e-15);
      EXPECT_NEAR(std::hypot(result.p_WT2.x(), result.p_WT2.y()), kCircle, 1e-15);
      EXPECT_NEAR(result.p_WT1.z(), p.z(), 1e-15);
      // The drawn arc runs from T1 to T2 round the circle.
      EXPECT_LT((result.arc_points.front() - result.p_WT1).norm(), 1e-12);
      EXPECT_LT((result.arc_points.back() - result.p_WT2).norm(), 1e-9);
    }
  }
  EXPECT_GT(wrapped, 500);
  EXPECT_GT(straight, 500);
}

TEST(WrapCylinderObstTest, HeightsFollowTheUnrolledLineAndTheArcLeavesOutTheRise) {
  const WrapCylinderObst obstacle(kRadius, WrapCylinderObst::Direction::kRightHand);
  int wrapped = 0;
  for (const auto& [p, s] : OutsidePairs(1000, 9, 0.05, false)) {
    const CrossSection expected = ExpectedCrossSection(p, s, 1);
    const WrapResult result = obstacle.Wrap(p, s, {});
    ASSERT_EQ(result.wrapped, expected.wraps);
    if (!expected.wraps) continue;
    ++wrapped;
    // Unrolled, the path is the straight line from P to S: G = hypot(cross-section length,
    // rise), and each piece rises in proportion to its cross-section length. OpenSim's length
    // is the two straight pieces of that line plus the arc's cross-section length only.
    const double across = expected.straight_p + expected.arc + expected.straight_s;
    const double rise = s.z() - p.z();
    const double unrolled = std::hypot(across, rise);
    EXPECT_NEAR(result.p_WT1.z(), p.z() + rise * expected.straight_p / across, 1e-9);
    EXPECT_NEAR(result.p_WT2.z(), s.z() - rise * expected.straight_s / across, 1e-9);
    const double opensim =
        (expected.straight_p + expected.straight_s) * unrolled / across + expected.arc;
    EXPECT_NEAR(PathLength(p, s, result), opensim, 1e-9);
    // Shorter than the geodesic (the helix) by the arc's missing rise.
    EXPECT_LE(PathLength(p, s, result), unrolled + 1e-12);
  }
  EXPECT_GT(wrapped, 200);
}

TEST(WrapCylinderObstTest, LengthIsContinuousWhereTheTurnStartsAtZero) {
  // S moves round from behind P's tangent line (a negative turn: no wrap) to ahead of it: the
  // turn passes through zero with Q = T, where the wrapped and straight paths meet.
  const WrapCylinderObst obstacle(kRadius, WrapCylinderObst::Direction::kRightHand);
  const Vec3 s(0.05, 0.0, 0.0);
  testing::ExpectContinuousAcrossEngagement(obstacle, {-0.05, 0.03, 0.0}, {-0.05, -0.05, 0.0}, s,
                                            20000, 1e-12);
}

TEST(WrapCylinderObstTest, NoWrapFromInsideTheCircle) {
  const WrapCylinderObst obstacle(kRadius, WrapCylinderObst::Direction::kRightHand);
  // Inside 0.8 r: no wrap, reported as a point inside; between 0.8 r and r the point is outside.
  const WrapResult inside = obstacle.Wrap({0.5 * kCircle, 0.0, 0.0}, {-0.05, 0.0, 0.0}, {});
  EXPECT_FALSE(inside.wrapped);
  EXPECT_TRUE(inside.point_inside);
  EXPECT_FALSE(obstacle.Wrap({0.9 * kRadius, 0.0, 0.0}, {-0.05, 0.0, 0.0}, {}).point_inside);
  EXPECT_THROW(WrapCylinderObst(0.0, WrapCylinderObst::Direction::kLeftHand), Error);
}

bool SegmentEntersSphere(const Vec3& p, const Vec3& s, double radius) {
  const Vec3 d = s - p;
  const double t = -p.dot(d) / d.squaredNorm();
  return t > 0.0 && t < 1.0 && (p + t * d).norm() < radius;
}

TEST(WrapSphereObstTest, PathIsTheGreatCircleOverTheSmallerSphereWhenTheSegmentEntersIt) {
  const WrapSphereObst obstacle(kRadius);
  int wrapped = 0, straight = 0;
  for (const auto& [p, s] :
       testing::RandomPairs(3000, 0.06, 17, false, [](const Vec3&a, const Vec3&b) {
         return a.norm() > 1.05 * kCircle && b.norm() > 1.05 * kCircle;
       })) {
    const WrapResult result = obstacle.Wrap(p, s, kOptions);
    // Within 1e-9 of grazing, rounding may decide either way.
    const Vec3 d = s - p;
    const double miss = (p + std::clamp(-p.dot(d) / d.squaredNorm(), 0.0, 1.0) * d).norm();
    if (std::abs(miss - kCircle) < 1e-9) continue;
    ASSERT_EQ(result.wrapped, SegmentEntersSphere(p, s, kCircle)) << p.transpose();
    EXPECT_FALSE(result.mandatory);
    if (!result.wrapped) {
      ++straight;
      continue;
    }
    ++wrapped;
    EXPECT_NEAR(PathLength(p, s, result), CircleWrapLength(p, s, kCircle, false), 1e-9);
    EXPECT_NEAR(result.p_WT1.norm(), kCircle, 1e-15);
    EXPECT_NEAR((result.p_WT1 - p).normalized().dot(result.p_WT1 / kCircle), 0.0, 1e-9);
    EXPECT_LT((result.arc_points.back() - result.p_WT2).norm(), 1e-9);
  }
  EXPECT_GT(wrapped, 300);
  EXPECT_GT(straight, 300);
}

TEST(WrapSphereObstTest, PointsInLineWithTheCentreAreReportedAsInside) {
  const WrapSphereObst obstacle(kRadius);
  const WrapResult result = obstacle.Wrap({0.05, 0.0, 0.0}, {-0.05, 0.0, 0.0}, {});
  EXPECT_FALSE(result.wrapped);
  EXPECT_TRUE(result.point_inside);
  EXPECT_THROW(WrapSphereObst(-1.0), Error);
}

}  // namespace
}  // namespace sinew::paths

// WrapSphere against the closed-form shortest path over a sphere (a great-circle arc between
// the tangent lines from P and S), tangency, OpenSim's engagement and quadrant rules.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/paths/wrap_sphere.h>

#include <numbers>

#include "wrap_checks.h"
#include "wrap_reference.h"

namespace sinew::paths {
namespace {

using testing::CircleWrapLength;
using testing::ExpectContinuousAcrossEngagement;
using testing::ExpectReversible;
using testing::ExpectWrapOnSide;
using testing::PathLength;
using testing::RandomPoint;

constexpr double kRadius = 1.0;
// Arc points asked for, so the drawn arc is checked too.
const WrapOptions kOptions{WrapOptions::Method::kHybrid, true, true, {}};

// True when the segment P-S passes strictly inside the sphere (closest point between P and S).
bool SegmentEntersSphere(const Vec3& p, const Vec3& s) {
  const Vec3 d = s - p;
  const double t = -p.dot(d) / d.squaredNorm();
  return t > 0.0 && t < 1.0 && (p + t * d).norm() < kRadius;
}

// Random pairs of points at least 5% of the radius outside the sphere whose segment enters it.
std::vector<std::pair<Vec3, Vec3>> CrossingPairs(int count) {
  return testing::RandomPairs(count, 4.0, 11, false, [](const Vec3& p, const Vec3& s) {
    return p.norm() > 1.05 * kRadius && s.norm() > 1.05 * kRadius && SegmentEntersSphere(p, s);
  });
}

TEST(WrapSphereTest, LengthIsTheGreatCircleShortestPath) {
  const WrapSphere sphere(kRadius, {});
  for (const auto& [p, s] : CrossingPairs(2000)) {
    const WrapResult result = sphere.Wrap(p, s, kOptions);
    ASSERT_TRUE(result.wrapped);
    const double expected = CircleWrapLength(p, s, kRadius, false);
    // Double rounding through acos of r/d with d >= 1.05 r: well under 1e-12 relative.
    EXPECT_NEAR(PathLength(p, s, result), expected, 1e-12 * expected);
    // Unconstrained, OpenSim reports a plain (not mandatory) wrap for a sphere.
    EXPECT_FALSE(result.mandatory);
  }
}

TEST(WrapSphereTest, TangentPointsLieOnTheSphereAndTheSegmentsTouchIt) {
  const WrapSphere sphere(kRadius, {});
  for (const auto& [p, s] : CrossingPairs(500)) {
    const WrapResult r = sphere.Wrap(p, s, kOptions);
    ASSERT_TRUE(r.wrapped);
    EXPECT_NEAR(r.p_WT1.norm(), kRadius, 1e-12);
    EXPECT_NEAR(r.p_WT2.norm(), kRadius, 1e-12);
    // The normal at T is T / r; a tangent segment is orthogonal to it.
    EXPECT_NEAR((r.p_WT1 - p).normalized().dot(r.p_WT1 / kRadius), 0.0, 1e-12);
    EXPECT_NEAR((s - r.p_WT2).normalized().dot(r.p_WT2 / kRadius), 0.0, 1e-12);
    // The drawn arc runs from T1 to T2 on the sphere, in the plane of P, S and the centre.
    ASSERT_GE(r.arc_points.size(), 2u);
    EXPECT_LT((r.arc_points.front() - r.p_WT1).norm(), 1e-12);
    EXPECT_LT((r.arc_points.back() - r.p_WT2).norm(), 1e-12);
    const Vec3 n = p.cross(s).normalized();
    for (const Vec3& point : r.arc_points) {
      EXPECT_NEAR(point.norm(), kRadius, 1e-12);
      EXPECT_NEAR(point.dot(n), 0.0, 1e-12);
    }
  }
}

TEST(WrapSphereTest, NoWrapWhenTheSegmentDoesNotEnterTheSphere) {
  const WrapSphere sphere(kRadius, {});
  // The line passes beside the sphere.
  EXPECT_FALSE(sphere.Wrap({-3, 1.5, 0}, {3, 1.5, 0}, kOptions).wrapped);
  // The line crosses it, but the segment ends before it.
  EXPECT_FALSE(sphere.Wrap({-5, 0.5, 0}, {-2, 0.5, 0}, kOptions).wrapped);
  // A point inside the sphere: OpenSim leaves the path straight.
  EXPECT_FALSE(sphere.Wrap({0.5, 0, 0}, {3, 0.5, 0}, kOptions).wrapped);
}

TEST(WrapSphereTest, QuadrantSendsThePathAroundItsActiveSide) {
  // The segment passes through the sphere above its centre (y = 0.5): free, the path goes over
  // the +y side; with quadrant -y it must go under, the longer way, by the closed form.
  const Vec3 p(-3, 0.5, 0);
  const Vec3 s(3, 0.5, 0);
  // Unconstrained, OpenSim's sphere wrap is a plain one, not mandatory.
  ExpectWrapOnSide(WrapSphere(kRadius, {}).Wrap(p, s, kOptions), p, s, 1, +1, false,
                   CircleWrapLength(p, s, kRadius, false));
  // Neither point is on the active side: a plain wrap, the long way under.
  const WrapResult below =
      WrapSphere(kRadius, ParseWrapQuadrant("-y", "test")).Wrap(p, s, kOptions);
  ExpectWrapOnSide(below, p, s, 1, -1, false, CircleWrapLength(p, s, kRadius, true));
  for (const Vec3& point : below.arc_points) EXPECT_LT(point.y(), 1e-12);
  // Both points on the active side: mandatory, over the top.
  ExpectWrapOnSide(WrapSphere(kRadius, ParseWrapQuadrant("+y", "test")).Wrap(p, s, kOptions), p, s,
                   1, +1, true, CircleWrapLength(p, s, kRadius, false));
}

TEST(WrapSphereTest, ThroughTheCentreEveryPlaneGivesTheClosedFormLength) {
  // The plane of P, S and the centre is undefined; OpenSim reuses its previous tangent points,
  // a stateless surface picks a plane (the quadrant's axis when constrained). Every plane
  // through the line gives the same length: 2 sqrt(9 - 1) + (pi - 2 acos(1/3)).
  const Vec3 p(-3, 0, 0);
  const Vec3 s(3, 0, 0);
  const double expected = 2 * std::sqrt(8.0) + std::numbers::pi - 2 * std::acos(1.0 / 3.0);
  const WrapResult free = WrapSphere(kRadius, {}).Wrap(p, s, kOptions);
  ASSERT_TRUE(free.wrapped);
  EXPECT_NEAR(PathLength(p, s, free), expected, 1e-12);
  const WrapResult below =
      WrapSphere(kRadius, ParseWrapQuadrant("-z", "test")).Wrap(p, s, kOptions);
  ASSERT_TRUE(below.wrapped);
  EXPECT_NEAR(PathLength(p, s, below), expected, 1e-12);
  EXPECT_LT(below.p_WT1.z(), 0.0);
  EXPECT_LT(below.p_WT2.z(), 0.0);
}

TEST(WrapSphereTest, SwappingPAndSReversesThePath) {
  ExpectReversible(WrapSphere(kRadius, {}), CrossingPairs(500), kOptions, 1e-12);
}

TEST(WrapSphereTest, LengthIsContinuousAsTheWrapEngages) {
  // P slides so that the segment goes from beside the sphere to through it.
  ExpectContinuousAcrossEngagement(WrapSphere(kRadius, {}), {-3.0, 0.998, 0.3}, {-3.0, 1.002, 0.3},
                                   {2.5, 1.0, -0.2}, 4000, 1e-13);
}

// The length of P -> T1 -> great circle -> T2 -> S for any T1, T2 on the sphere.
double LengthThrough(const Vec3& p, const Vec3& t1, const Vec3& t2, const Vec3& s) {
  const double angle = std::atan2(t1.cross(t2).norm(), t1.dot(t2));
  return (t1 - p).norm() + kRadius * angle + (s - t2).norm();
}

TEST(WrapSphereTest, MovingATangentPointChangesTheLengthOnlyToSecondOrder) {
  // The contract's premise for moment arms: dL/dh = 0 when T1 (or T2) moves along the surface
  // by h. A central difference with h = 1e-5 has truncation ~h^2 L''' / 6 and rounding
  // ~1e-16 L / h, both below 1e-9; a point off tangency would give dL/dh of order one.
  const WrapSphere sphere(kRadius, {});
  std::mt19937 random(5);
  const double h = 1e-5;
  int compared = 0;
  for (const auto& [p, s] : CrossingPairs(400)) {
    const WrapResult r = sphere.Wrap(p, s, kOptions);
    ASSERT_TRUE(r.wrapped);
    // The great-circle distance's third derivative grows as 1 / angle^2 for short arcs; at
    // 0.1 rad and more its truncation error here stays under 1e-9.
    if (r.arc_length < 0.1 * kRadius) continue;
    ++compared;
    const Vec3 axis = RandomPoint(random, 1.0).normalized();
    const auto moved = [&](const Vec3& t, double angle) {
      return Eigen::AngleAxisd(angle, axis) * t;
    };
    const double d_t1 = (LengthThrough(p, moved(r.p_WT1, h), r.p_WT2, s) -
                         LengthThrough(p, moved(r.p_WT1, -h), r.p_WT2, s)) /
                        (2 * h);
    const double d_t2 = (LengthThrough(p, r.p_WT1, moved(r.p_WT2, h), s) -
                         LengthThrough(p, r.p_WT1, moved(r.p_WT2, -h), s)) /
                        (2 * h);
    EXPECT_NEAR(d_t1, 0.0, 1e-8);
    EXPECT_NEAR(d_t2, 0.0, 1e-8);
  }
  EXPECT_GT(compared, 200);
}

TEST(WrapSphereTest, RejectsANonPositiveRadius) {
  EXPECT_THROW(WrapSphere(0.0, {}), Error);
  EXPECT_THROW(WrapSphere(-1.0, {}), Error);
}

}  // namespace
}  // namespace sinew::paths

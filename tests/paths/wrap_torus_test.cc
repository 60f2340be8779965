// WrapTorus against closed forms: OpenSim wraps a segment over a cylinder of the tube's radius
// laid along the ring at the ring point nearest the segment, on the side facing the torus's
// axis. In a plane through the axis (a meridian plane) that is the tube's circle, so a path in
// such a plane has the circle's closed-form length and is the shortest path there.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/paths/wrap_torus.h>

#include <cmath>
#include <numbers>

#include "wrap_checks.h"
#include "wrap_reference.h"

namespace sinew::paths {
namespace {

using testing::CircleWrapLength;
using testing::ExpectContinuousAcrossEngagement;
using testing::PathLength;

// The dimensions of test_wrapAllVis.osim's torus (m).
constexpr double kTube = 0.035;  // inner_radius
constexpr double kRing = 0.08;   // outer_radius
const WrapOptions kOptions{WrapOptions::Method::kHybrid, true, true, {}};

// p turned by `angle` about W's z axis (the torus's axis of symmetry).
Vec3 TurnedAboutAxis(const Vec3& p, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * p.x() - s * p.y(), s * p.x() + c * p.y(), p.z()};
}

// Distance of a point from the torus surface measured in its meridian plane: |rho - R| and z
// give the distance from the ring circle, less the tube's radius.
double OffTorusSurface(const Vec3& p) {
  return std::hypot(std::hypot(p.x(), p.y()) - kRing, p.z()) - kTube;
}

// P and S straddling the ring at (R, 0, 0) along a line parallel to the axis, `a` further out
// from the axis than the ring, `h` above and below it, turned by `angle` about the axis.
std::pair<Vec3, Vec3> AcrossTheRing(double a, double h, double angle) {
  return {TurnedAboutAxis({kRing + a, 0.0, -h}, angle),
          TurnedAboutAxis({kRing + a, 0.0, h}, angle)};
}

// The closed form in the meridian plane: the tube's cross-section is the circle of radius r
// about the ring point; P and S, relative to it, at (a, -h) and (a, h). The path goes round the
// side facing the axis; that is the short way when the segment passes on that side (a <= 0).
double MeridianWrapLength(double a, double h) {
  return CircleWrapLength(Vec3(a, -h, 0.0), Vec3(a, h, 0.0), kTube, a > 0.0);
}

TEST(WrapTorusTest, PathsInAMeridianPlaneFollowTheTubesCircle) {
  const WrapTorus torus(kTube, kRing, {});
  for (const double a : {-0.02, -0.01, 0.0, 0.01, 0.03}) {
    for (const double angle : {0.0, 0.7, 2.0, -2.9}) {
      const auto [p, s] = AcrossTheRing(a, 0.06, angle);
      const WrapResult result = torus.Wrap(p, s, kOptions);
      ASSERT_TRUE(result.wrapped) << a << " " << angle;
      // OpenSim's torus reports every wrap as a plain one.
      EXPECT_FALSE(result.mandatory);
      // Rounding of acos(r/d) and the frame change at d ~ 2 r: 1e-15 m; 1e-14 allowed.
      EXPECT_NEAR(PathLength(p, s, result), MeridianWrapLength(a, 0.06), 1e-14) << a;
      EXPECT_NEAR(OffTorusSurface(result.p_WT1), 0.0, 1e-14);
      EXPECT_NEAR(OffTorusSurface(result.p_WT2), 0.0, 1e-14);
      // The path lies on the hole side of the tube: closer to the axis than the ring.
      EXPECT_LT(std::hypot(result.p_WT1.x(), result.p_WT1.y()), kRing);
      for (const Vec3& point : result.arc_points) {
        EXPECT_NEAR(OffTorusSurface(point), 0.0, 1e-14);
        EXPECT_LE(std::hypot(point.x(), point.y()), kRing + 1e-15);
      }
    }
  }
}

TEST(WrapTorusTest, SegmentsClearOfTheTubeStayStraight) {
  const WrapTorus torus(kTube, kRing, {});
  // Through the hole, never within the tube's radius of the ring.
  EXPECT_FALSE(torus.Wrap({0.01, 0.005, -0.1}, {0.015, -0.01, 0.1}, kOptions).wrapped);
  EXPECT_FALSE(torus.Wrap({-0.02, 0.02, -0.1}, {0.02, 0.0, 0.1}, kOptions).wrapped);
  // Above the hole.
  EXPECT_FALSE(torus.Wrap({-0.03, 0.0, 0.1}, {0.03, 0.01, 0.12}, kOptions).wrapped);
}

TEST(WrapTorusTest, ASegmentOutsideTheRingIsPulledThroughTheHole) {
  // OpenSim's cylinder is constrained to the side facing the axis (+x), so a segment entirely
  // outside the ring wraps round the inside of the tube, the long way (MeridianWrapLength with
  // a > 0), as if the path ran through the hole.
  const WrapTorus torus(kTube, kRing, {});
  const auto [p, s] = AcrossTheRing(0.1, 0.05, 0.4);
  const WrapResult result = torus.Wrap(p, s, kOptions);
  ASSERT_TRUE(result.wrapped);
  EXPECT_NEAR(PathLength(p, s, result), MeridianWrapLength(0.1, 0.05), 1e-14);
}

TEST(WrapTorusTest, LengthIsContinuousAsTheWrapEngagesAndDisengages) {
  const WrapTorus torus(kTube, kRing, {});
  // In the meridian plane y = 0: from crossing the tube (wrapped) to clear of it.
  ExpectContinuousAcrossEngagement(torus, {0.06, 0.0, -0.06}, {0.005, 0.0, -0.06},
                                   {0.06, 0.0, 0.06}, 20000, 1e-14);
  // Out of the plane: the ring point follows the segment round the ring.
  ExpectContinuousAcrossEngagement(torus, {0.06, 0.012, -0.06}, {0.005, -0.004, -0.06},
                                   {0.058, 0.01, 0.06}, 20000, 1e-14);
}

TEST(WrapTorusTest, TensionAtAnEndIsMinusTheLengthGradient) {
  // In a meridian plane OpenSim's path is the shortest one, so moving P by dx changes the length
  // by e . dx, e the unit direction from T1 to P: the force of a tension T on P is -T dL/dx,
  // with dL/dx taken here by central differences (steps h = 1e-6 m in the plane).
  const WrapTorus torus(kTube, kRing, {});
  const Vec3 s(0.065, 0.0, 0.06);
  const auto length = [&](const Vec3& p) { return PathLength(p, s, torus.Wrap(p, s, {})); };
  constexpr double h = 1e-6;
  for (const Vec3& p : {Vec3(0.06, 0.0, -0.06), Vec3(0.07, 0.0, -0.05), Vec3(0.03, 0.0, -0.07)}) {
    const WrapResult result = torus.Wrap(p, s, {});
    ASSERT_TRUE(result.wrapped);
    const Vec3 e = (p - result.p_WT1).normalized();
    for (const Vec3& direction : {Vec3(Vec3::UnitX()), Vec3(Vec3::UnitZ())}) {
      const double difference = (length(p + h * direction) - length(p - h * direction)) / (2 * h);
      // Truncation h^2 L''' / 6 with L''' ~ 1 / (distance to T1)^2 ~ 1e3: 2e-10; rounding
      // 1e-17 / 1e-6: 1e-11.
      EXPECT_NEAR(difference, e.dot(direction), 1e-9) << p.transpose();
    }
  }
}

TEST(WrapTorusTest, ARingPointAtTheNearestPartOfTheSegment) {
  // A line parallel to the axis at distance d from it: OpenSim's residual is 2 (z - z0) there
  // (rho is constant), so the ring point is straight out from the line's point at z = 0.
  const Vec3 c = *FindTorusRingPoint({0.03, 0.04, -0.1}, {0.03, 0.04, 0.2}, kRing, {});
  EXPECT_NEAR((c - Vec3(0.6, 0.8, 0.0) * kRing).norm(), 0.0, 1e-15);
  // In the plane z = 0.01, along x: the residual vanishes where the line is nearest the circle
  // of radius 2 R (OpenSim's factor, docs/wrapping.md), x = +-2R; the two ends find the two
  // points, equally far from the ring, and OpenSim keeps the second (from S).
  const Vec3 from_s = *FindTorusRingPoint({-0.3, 0.0, 0.01}, {0.25, 0.0, 0.01}, kRing, {});
  EXPECT_NEAR((from_s - Vec3(kRing, 0, 0)).norm(), 0.0, 1e-15);
  // Off the axis (y = y0): the points of the line at distance 2R from the axis,
  // x = +-sqrt(4R^2 - y0^2), equally far from the ring, so again S's is kept.
  const double y0 = 0.05;
  const double x = std::sqrt(4 * kRing * kRing - y0 * y0);
  const Vec3 off = *FindTorusRingPoint({-0.3, y0, 0.0}, {0.3, y0, 0.0}, kRing, {});
  EXPECT_NEAR((off - Vec3(x, y0, 0.0).normalized() * kRing).norm(), 0.0, 1e-12);
  // A quadrant keeps a point on its side, and none when neither is.
  const Vec3 negative =
      *FindTorusRingPoint({-0.3, y0, 0.0}, {0.3, y0, 0.0}, kRing, WrapQuadrant{0, -1});
  EXPECT_NEAR((negative - Vec3(-x, y0, 0.0).normalized() * kRing).norm(), 0.0, 1e-12);
  EXPECT_FALSE(FindTorusRingPoint({-0.3, y0, 0.0}, {0.3, y0, 0.0}, kRing, WrapQuadrant{1, -1}));
}

TEST(WrapTorusTest, ReversingTheSegmentGivesTheSamePath) {
  const WrapTorus torus(kTube, kRing, {});
  std::vector<std::pair<Vec3, Vec3>> pairs;
  for (const double a : {-0.02, 0.0, 0.02}) pairs.push_back(AcrossTheRing(a, 0.07, 1.1));
  testing::ExpectReversible(torus, pairs, {}, 1e-14);
}

TEST(WrapTorusTest, RefusesRadiiThatDoNotMakeATorus) {
  EXPECT_THROW(WrapTorus(0.05, 0.05, {}), Error);
  EXPECT_THROW(WrapTorus(0.0, 0.05, {}), Error);
  EXPECT_THROW(WrapTorus(0.01, INFINITY, {}), Error);
}

}  // namespace
}  // namespace sinew::paths

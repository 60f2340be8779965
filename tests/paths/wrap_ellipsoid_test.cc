// WrapEllipsoid against closed forms: equal semi-axes give the great-circle path of a sphere; a
// path in a principal plane follows the ellipse of that plane. OpenSim's construction finds the
// tangent points by an iteration that stops at a squared residual of 1e-8 (in units where the
// semi-axes average 1) and measures the arc as a polyline of 1 mm chords, so the bounds are
// those two errors, measured here: how far the tangent points are off the surface (eps), and
// the chords' shortfall from the arc (at most arc (kappa l)^2 / 24 for chords l on a curve of
// curvature kappa).
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/paths/wrap_ellipsoid.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>

#include "wrap_checks.h"
#include "wrap_reference.h"

namespace sinew::paths {
namespace {

using testing::CircleWrapLength;
using testing::PathLength;

constexpr double kRadius = 0.02;  // bone sized: OpenSim's chords are 1 mm
const WrapOptions kHybrid{WrapOptions::Method::kHybrid, true, true, {}};
// The tangent-point iteration stops when its squared residuals sum below 1e-8, so the point's
// residual on the ellipsoid, |x / radii|^2 - 1, may be up to 1e-4: off the surface by up to
// 1e-4 / |gradient| <= 5e-5 times the largest semi-axis.
constexpr double kStoppingBound = 5e-5;

// How far p is off the ellipsoid, in m along its gradient (first order).
double OffSurface(const Vec3& radii, const Vec3& p) {
  const Vec3 scaled = p.cwiseQuotient(radii);
  const Vec3 gradient = 2.0 * p.cwiseQuotient(radii.cwiseProduct(radii));
  return std::abs(scaled.squaredNorm() - 1.0) / gradient.norm();
}

// The longest chord of the drawn arc (m).
double LongestChord(const WrapResult& result) {
  double longest = 0.0;
  for (size_t i = 0; i + 1 < result.arc_points.size(); ++i) {
    longest = std::max(longest, (result.arc_points[i + 1] - result.arc_points[i]).norm());
  }
  return longest;
}

// Random segments through a sphere of kRadius, ends at least 5% outside it.
std::vector<std::pair<Vec3, Vec3>> CrossingPairs(int count, unsigned seed) {
  return testing::RandomPairs(count, 4.0 * kRadius, seed, false, [](const Vec3& p, const Vec3& s) {
    const Vec3 d = s - p;
    const double t = -p.dot(d) / d.squaredNorm();
    return p.norm() > 1.05 * kRadius && s.norm() > 1.05 * kRadius && t > 0.0 && t < 1.0 &&
           (p + t * d).norm() < 0.98 * kRadius;
  });
}

TEST(WrapEllipsoidTest, EqualSemiAxesGiveTheGreatCirclePath) {
  const Vec3 radii = Vec3::Constant(kRadius);
  double worst_eps = 0.0, worst_arc = 0.0, worst_length = 0.0;
  for (WrapOptions::Method method : {WrapOptions::Method::kHybrid, WrapOptions::Method::kMidpoint,
                                     WrapOptions::Method::kAxial}) {
    const WrapEllipsoid ellipsoid(radii, {});
    WrapOptions options = kHybrid;
    options.method = method;
    for (const auto& [p, s] : CrossingPairs(300, 5)) {
      const WrapResult result = ellipsoid.Wrap(p, s, options);
      ASSERT_TRUE(result.wrapped);
      EXPECT_TRUE(result.mandatory);
      const double eps = std::max(OffSurface(radii, result.p_WT1), OffSurface(radii, result.p_WT2));
      worst_eps = std::max(worst_eps, eps);
      // The arc is the polyline of n equal chords of the great circle through T1 and T2.
      const double chord = (result.p_WT1 - result.p_WT2).norm();
      const int n = std::min(static_cast<int>(chord / 0.001), 499);
      const double angle = std::atan2(result.p_WT1.cross(result.p_WT2).norm(),
                                      result.p_WT1.dot(result.p_WT2));
      const double polyline = n == 0 ? chord : n * 2.0 * kRadius * std::sin(angle / (2.0 * n));
      worst_arc = std::max(worst_arc, std::abs(result.arc_length - polyline));
      EXPECT_NEAR(result.arc_length, polyline, 4.0 * eps + 1e-15);
      // The whole path: the shortest path over the sphere less the chords' shortfall.
      const double shortfall = kRadius * angle - polyline;
      const double expected = CircleWrapLength(p, s, kRadius, false) - shortfall;
      worst_length = std::max(worst_length, std::abs(PathLength(p, s, result) - expected));
      EXPECT_NEAR(PathLength(p, s, result), expected, 4.0 * eps + 1e-14);
    }
  }
  std::cout << "equal semi-axes: tangent points off the surface by up to " << worst_eps
            << " m; arc vs the great circle's chords " << worst_arc << " m; path vs closed form "
            << worst_length << " m\n";
  EXPECT_LT(worst_eps, kStoppingBound * kRadius);
}

// The arc length of the ellipse (x/a)^2 + (y/b)^2 = 1 between parametric angles t1 and t2 (the
// short way), by Simpson's rule on 20000 intervals.
double EllipseArc(double a, double b, double t1, double t2) {
  double dt = std::remainder(t2 - t1, 2.0 * std::numbers::pi);
  const int n = 20000;
  const auto speed = [&](double t) { return std::hypot(a * std::sin(t), b * std::cos(t)); };
  double sum = speed(t1) + speed(t1 + dt);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * speed(t1 + dt * i / n);
  return std::abs(dt) / n / 3.0 * sum;
}

// In the principal plane z = 0 of an ellipsoid whose z semi-axis is the longest: every nearest
// surface point OpenSim's plane choice takes then lies in that plane (with a shorter z axis the
// nearest point of an interior point leaves it, and so does OpenSim's path).
TEST(WrapEllipsoidTest, APathInAPrincipalPlaneFollowsItsEllipse) {
  const Vec3 radii(0.035, 0.02, 0.05);
  const WrapEllipsoid ellipsoid(radii, {});
  const double a = radii.x(), b = radii.y();
  const double curvature = a / (b * b);  // the ellipse's largest
  double worst_eps = 0.0, worst_arc = 0.0;
  int wrapped = 0;
  for (auto [p, s] : testing::RandomPairs(400, 0.1, 9, false, [](const Vec3&, const Vec3&) {
         return true;
       })) {
    p.z() = s.z() = 0.0;
    const WrapResult result = ellipsoid.Wrap(p, s, kHybrid);
    if (!result.wrapped) continue;
    ++wrapped;
    // In the plane, and each straight segment tangent to the ellipse there.
    EXPECT_EQ(result.p_WT1.z(), 0.0);
    EXPECT_EQ(result.p_WT2.z(), 0.0);
    const double eps = std::max(OffSurface(radii, result.p_WT1), OffSurface(radii, result.p_WT2));
    worst_eps = std::max(worst_eps, eps);
    for (const auto& [t, x] : {std::pair{result.p_WT1, p}, std::pair{result.p_WT2, s}}) {
      const Vec3 normal = t.cwiseQuotient(radii.cwiseProduct(radii)).normalized();
      EXPECT_LT(std::abs((x - t).normalized().dot(normal)), 1e-3);
    }
    // The arc: the ellipse's between the tangent points, less the chords' shortfall.
    const double t1 = std::atan2(result.p_WT1.y() / b, result.p_WT1.x() / a);
    const double t2 = std::atan2(result.p_WT2.y() / b, result.p_WT2.x() / a);
    const double exact = EllipseArc(a, b, t1, t2);
    const double chord = LongestChord(result);
    const double shortfall = exact * std::pow(curvature * chord, 2) / 24.0;
    worst_arc = std::max(worst_arc, std::abs(result.arc_length - exact));
    EXPECT_LE(result.arc_length, exact + 4.0 * eps + 1e-12);
    EXPECT_GE(result.arc_length, exact - shortfall - 4.0 * eps - 1e-12);
  }
  std::cout << wrapped << " planar wraps: tangent points off the surface by up to " << worst_eps
            << " m; arc vs the ellipse " << worst_arc << " m\n";
  EXPECT_GT(wrapped, 50);
  EXPECT_LT(worst_eps, kStoppingBound * radii.maxCoeff());
}

TEST(WrapEllipsoidTest, QuadrantSendsThePathAroundItsActiveSide) {
  const Vec3 radii = Vec3::Constant(kRadius);
  const Vec3 p(-3.0 * kRadius, -0.3 * kRadius, 0.0), s(3.0 * kRadius, -0.2 * kRadius, 0.0);
  // Unconstrained the path passes below (-y), the short way; with +y it goes over the top.
  const WrapResult free = WrapEllipsoid(radii, {}).Wrap(p, s, kHybrid);
  ASSERT_TRUE(free.wrapped);
  EXPECT_LT(free.p_WT1.y(), 0.0);
  const WrapResult over = WrapEllipsoid(radii, {1, 1}).Wrap(p, s, kHybrid);
  ASSERT_TRUE(over.wrapped);
  EXPECT_TRUE(over.mandatory);
  EXPECT_GT(over.p_WT1.y(), 0.0);
  EXPECT_GT(over.p_WT2.y(), 0.0);
  // The great-circle path the long way round, less its chords' shortfall (<= arc/24 (l/R)^2).
  const double expected = CircleWrapLength(p, s, kRadius, true);
  const double shortfall = over.arc_length * std::pow(LongestChord(over) / kRadius, 2) / 24.0;
  EXPECT_LE(PathLength(p, s, over), expected + 1e-7);
  EXPECT_GE(PathLength(p, s, over), expected - shortfall - 1e-7);
}

TEST(WrapEllipsoidTest, LengthIsContinuousAsTheWrapEngages) {
  // P slides so that the segment goes from beside the ellipsoid to through it.
  const WrapEllipsoid ellipsoid(Vec3(0.035, 0.02, 0.025), {});
  testing::ExpectContinuousAcrossEngagement(ellipsoid, {-0.1, 0.0195, 0.003},
                                            {-0.1, 0.0205, 0.003}, {0.09, 0.02, -0.002}, 2000,
                                            1e-7);
}

TEST(WrapEllipsoidTest, NoWrapWhenAPointIsInsideOrTheSegmentMisses) {
  const WrapEllipsoid ellipsoid(Vec3(0.035, 0.02, 0.025), {});
  const WrapResult inside = ellipsoid.Wrap({0.01, 0.0, 0.0}, {0.1, 0.0, 0.0}, kHybrid);
  EXPECT_FALSE(inside.wrapped);
  EXPECT_TRUE(inside.point_inside);
  EXPECT_FALSE(ellipsoid.Wrap({-0.1, 0.03, 0.0}, {0.1, 0.03, 0.0}, kHybrid).wrapped);
  // Stops short of the ellipsoid.
  EXPECT_FALSE(ellipsoid.Wrap({-0.1, 0.0, 0.0}, {-0.05, 0.001, 0.0}, kHybrid).wrapped);
}

TEST(WrapEllipsoidTest, RejectsNonPositiveRadii) {
  EXPECT_THROW(WrapEllipsoid(Vec3(0.01, 0.0, 0.01), {}), Error);
  EXPECT_THROW(WrapEllipsoid(Vec3(0.01, -1.0, 0.01), {}), Error);
}

}  // namespace
}  // namespace sinew::paths

// OpenSim's WrapDoubleCylinderObst against closed forms: with the V cylinder out of the way, the
// path over U alone is the unrolled straight line round U's circle (its own radius, the rise
// included), which at one height is WrapCylinderObst's path over a cylinder of radius r / 0.8;
// with both cylinders engaged in one plane, the path is the tangent lines and arcs drawn by hand
// (the common outer tangent for two right-handed cylinders, the crossing inner tangent for a
// right- and a left-handed one); a path length moves no more than its end point.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/paths/obstacle_arc.h>
#include <sinew/paths/wrap_cylinder_obst.h>
#include <sinew/paths/wrap_double_cylinder_obst.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <random>

namespace sinew::paths {
namespace {

using Direction = WrapDoubleCylinderObst::Direction;
constexpr double kPi = std::numbers::pi;
constexpr double kRadius = 0.02;  // both cylinders (m)

// The path's length from P to S through what the wrap gives.
double PathLength(const Vec3& p, const Vec3& s, const WrapResult& r) {
  double length = 0.0;
  Vec3 at = p;
  if (r.on_first) {
    length += (r.p_WT1 - at).norm() + r.arc_length;
    at = r.p_WT2;
  }
  if (r.on_second) {
    length += (r.p_WT3 - at).norm() + r.second_arc_length;
    at = r.p_WT4;
  }
  return length + (s - at).norm();
}

// Options with V's frame at X_WV.
WrapOptions At(const Transform& X_WV) {
  WrapOptions options;
  options.X_WV = X_WV;
  return options;
}

// The path round one circle of radius r about W's z, turning `turn`, from the geometry: the
// turn from P's tangent point to S's is the angle from P to S that way less acos(r / d) at each
// end; it wraps when that turn is 0 to 180 degrees and (OpenSim's engagement test) the line
// through P and S passes within r of the axis. Length: the unrolled straight line.
struct OneCircle {
  bool wraps;
  double length;
};
OneCircle ExpectedOneCircle(const Vec3& p, const Vec3& s, double r, int turn) {
  const double dp = std::hypot(p.x(), p.y()), ds = std::hypot(s.x(), s.y());
  double between = turn * (std::atan2(s.y(), s.x()) - std::atan2(p.y(), p.x()));
  between = std::fmod(between + 4 * kPi, 2 * kPi);
  const double angle = between - std::acos(r / dp) - std::acos(r / ds);
  const double line_distance =
      std::abs(p.x() * s.y() - p.y() * s.x()) / std::hypot(s.x() - p.x(), s.y() - p.y());
  const bool wraps = angle >= 0.0 && angle <= kPi && line_distance <= r;
  const double unrolled = std::sqrt(dp * dp - r * r) + r * angle + std::sqrt(ds * ds - r * r);
  return {wraps, wraps ? std::hypot(unrolled, s.z() - p.z()) : (s - p).norm()};
}

TEST(WrapDoubleCylinderObstTest, WithVOutOfTheWayTheUPathIsTheUnrolledLine) {
  // V 10 m away along y, its axis along z: a line reaches it within its radius only when
  // nearly parallel to y; such pairs are skipped (checked from the geometry).
  const Transform X_WV = Transform::Translation(Vec3(0.0, 10.0, 0.0));
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-0.08, 0.08);
  int wrapped = 0, straight = 0;
  double worst = 0.0;
  for (const Direction direction : {Direction::kRightHand, Direction::kLeftHand}) {
    const int turn = direction == Direction::kRightHand ? 1 : -1;
    const WrapDoubleCylinderObst obstacle(kRadius, direction, kRadius, Direction::kRightHand);
    for (int i = 0; i < 4000; ++i) {
      const Vec3 p(coordinate(random), coordinate(random), coordinate(random));
      const Vec3 s(coordinate(random), coordinate(random), coordinate(random));
      if (std::hypot(p.x(), p.y()) < 1.05 * kRadius || std::hypot(s.x(), s.y()) < 1.05 * kRadius) {
        continue;
      }
      const Vec3 d = (s - p).normalized();
      if (std::abs(d.x()) < 1e-2) continue;  // a line that might reach V
      // V is also tested on the line from U's tangent point T (within kRadius of U's axis) to
      // S: skip S when the line from S towards V's axis passes within 1.1 kRadius of U's axis
      // (T's offset moves that line by at most kRadius there, plus 3e-4 m at V). Such a line
      // passes V 10 m away within its 2 cm only by rounding, which differs between compilers
      // (a clang build took one such sample into the two-cylinder branch).
      const Eigen::Vector2d towards_v = (Eigen::Vector2d(0.0, 10.0) - s.head<2>()).normalized();
      if (std::abs(s.x() * towards_v.y() - s.y() * towards_v.x()) < 1.1 * kRadius) continue;
      const OneCircle expected = ExpectedOneCircle(p, s, kRadius, turn);
      const WrapResult result = obstacle.Wrap(p, s, At(X_WV));
      ASSERT_TRUE(result.wrapped);  // OpenSim reports a wrap whatever happens
      EXPECT_FALSE(result.on_second);
      ASSERT_EQ(result.on_first, expected.wraps) << p.transpose() << " / " << s.transpose();
      // 1e-9 m: the acos of a chord's cosine loses up to sqrt(eps) of the angle near zero.
      EXPECT_NEAR(PathLength(p, s, result), expected.length, 1e-9);
      worst = std::max(worst, std::abs(PathLength(p, s, result) - expected.length));
      (expected.wraps ? wrapped : straight)++;
      if (!expected.wraps) continue;
      EXPECT_NEAR(std::hypot(result.p_WT1.x(), result.p_WT1.y()), kRadius, 1e-15);
      EXPECT_NEAR(std::hypot(result.p_WT2.x(), result.p_WT2.y()), kRadius, 1e-15);
    }
  }
  std::cout << "U alone: " << wrapped << " wrapped, " << straight << " straight; worst length "
            << "error " << worst << " m\n";
  EXPECT_GT(wrapped, 500);
  EXPECT_GT(straight, 500);
}

TEST(WrapDoubleCylinderObstTest, AtOneHeightUAloneIsWrapCylinderObstOfRadiusOverPointEight) {
  const Transform X_WV = Transform::Translation(Vec3(0.0, 10.0, 0.0));
  const WrapDoubleCylinderObst obstacle(kRadius, Direction::kLeftHand, kRadius,
                                        Direction::kRightHand);
  const WrapCylinderObst single(kRadius / kObstacleRadiusFraction,
                                WrapCylinderObst::Direction::kLeftHand);
  std::mt19937 random(8);
  std::uniform_real_distribution<double> coordinate(-0.08, 0.08);
  int compared = 0;
  for (int i = 0; i < 3000; ++i) {
    const double z = coordinate(random);
    const Vec3 p(coordinate(random), coordinate(random), z), s(coordinate(random), 0.01, z);
    if (std::hypot(p.x(), p.y()) < 1.05 * kRadius || std::hypot(s.x(), s.y()) < 1.05 * kRadius) {
      continue;
    }
    const WrapResult double_result = obstacle.Wrap(p, s, At(X_WV));
    const WrapResult single_result = single.Wrap(p, s, WrapOptions{});
    // WrapCylinderObst has no engagement test: where it wraps and the line misses U, the double
    // obstacle stays straight; everywhere else the two agree.
    if (!double_result.on_first) continue;
    ASSERT_TRUE(single_result.wrapped);
    EXPECT_LT((double_result.p_WT1 - single_result.p_WT1).norm(), 1e-12);
    EXPECT_LT((double_result.p_WT2 - single_result.p_WT2).norm(), 1e-12);
    EXPECT_NEAR(double_result.arc_length, single_result.arc_length, 1e-12);
    ++compared;
  }
  EXPECT_GT(compared, 300);
}

// Two right-handed cylinders of radius r, U at the origin and V at (d, 0, 0), and P, S below
// them mirror images about x = d / 2: the path runs under both along the outer tangent y = -r.
TEST(WrapDoubleCylinderObstTest, BothEngagedAlongTheOuterTangentInOnePlane) {
  const double d = 0.1, a = 0.05, b = 0.01;
  const WrapDoubleCylinderObst obstacle(kRadius, Direction::kRightHand, kRadius,
                                        Direction::kRightHand);
  for (const double z : {0.0, 0.03}) {
    const Vec3 p(-a, -b, z), s(d + a, -b, z);
    // Each end: the tangent from P, then the arc counter-clockwise to (0, -r).
    const double dp = std::hypot(a, b);
    const double q_angle = std::atan2(-b, -a) + std::acos(kRadius / dp);
    const double arc_angle = -kPi / 2 - q_angle;
    ASSERT_GT(arc_angle, 0.0);
    const double expected = 2 * (std::sqrt(dp * dp - kRadius * kRadius) + kRadius * arc_angle) + d;
    const WrapResult result = obstacle.Wrap(p, s, At(Transform::Translation(Vec3(d, 0.0, 0.0))));
    ASSERT_TRUE(result.on_first && result.on_second);
    EXPECT_NEAR(PathLength(p, s, result), expected, 1e-12);
    std::cout << "outer tangent at height " << z << ": length error "
              << PathLength(p, s, result) - expected << " m, crossing points off by "
              << (result.p_WT2 - Vec3(0.0, -kRadius, z)).norm() << " and "
              << (result.p_WT3 - Vec3(d, -kRadius, z)).norm() << " m\n";
    // Newton stops when the entry point moves less than 1e-12 m in all.
    EXPECT_LT((result.p_WT2 - Vec3(0.0, -kRadius, z)).norm(), 1e-11);
    EXPECT_LT((result.p_WT3 - Vec3(d, -kRadius, z)).norm(), 1e-11);
    EXPECT_NEAR(result.arc_length, kRadius * arc_angle, 1e-12);
    EXPECT_NEAR(result.second_arc_length, kRadius * arc_angle, 1e-12);
  }
}

// The same cylinders with S 4 cm above P: for parallel axes the heights over U follow the
// unrolled line from P to V's entry point and over V the one from U's exit point to S; sharing
// the crossing segment, they are one line, so the path is the straight line of the whole
// path unrolled (its length the hypotenuse of the plane path and the rise), and the crossing
// points are at heights in proportion to the plane path's length before them.
TEST(WrapDoubleCylinderObstTest, BothEngagedAtDifferentHeightsIsTheUnrolledLine) {
  const double d = 0.1, a = 0.05, b = 0.01, rise = 0.04;
  const WrapDoubleCylinderObst obstacle(kRadius, Direction::kRightHand, kRadius,
                                        Direction::kRightHand);
  const Vec3 p(-a, -b, 0.0), s(d + a, -b, rise);
  const double dp = std::hypot(a, b);
  const double arc_angle = -kPi / 2 - (std::atan2(-b, -a) + std::acos(kRadius / dp));
  const double to_u_exit = std::sqrt(dp * dp - kRadius * kRadius) + kRadius * arc_angle;
  const double plane = 2 * to_u_exit + d;
  const WrapResult result = obstacle.Wrap(p, s, At(Transform::Translation(Vec3(d, 0.0, 0.0))));
  ASSERT_TRUE(result.on_first && result.on_second);
  EXPECT_NEAR(PathLength(p, s, result), std::hypot(plane, rise), 1e-12);
  std::cout << "outer tangent rising " << rise << " m: length error "
            << PathLength(p, s, result) - std::hypot(plane, rise) << " m\n";
  EXPECT_LT((result.p_WT2 - Vec3(0.0, -kRadius, rise * to_u_exit / plane)).norm(), 1e-11);
  EXPECT_LT((result.p_WT3 - Vec3(d, -kRadius, rise * (to_u_exit + d) / plane)).norm(), 1e-11);
}

// The points drawn along both arcs: each arc from its first tangent point to its second, on its
// cylinder's surface (U's axis is W's z, V's is at x = d), and their chords' sum within the
// sampling's bound of the arc's length (5 degree steps: a chord is 2 r sin(a / 2), short of the
// arc r a by at most a^2 / 24 relative, 3.2e-4).
TEST(WrapDoubleCylinderObstTest, BothArcsAreSampledForDrawing) {
  const double d = 0.1, a = 0.05, b = 0.01, rise = 0.04;
  const WrapDoubleCylinderObst obstacle(kRadius, Direction::kRightHand, kRadius,
                                        Direction::kRightHand);
  const Vec3 p(-a, -b, 0.0), s(d + a, -b, rise);
  WrapOptions options = At(Transform::Translation(Vec3(d, 0.0, 0.0)));
  options.with_arc_points = true;
  const WrapResult result = obstacle.Wrap(p, s, options);
  ASSERT_TRUE(result.on_first && result.on_second);
  const auto check_arc = [&](const std::vector<Vec3>& arc, const Vec3& from, const Vec3& to,
                             double axis_x, double arc_length) {
    ASSERT_GE(arc.size(), 2u);
    EXPECT_LT((arc.front() - from).norm(), 1e-12);
    EXPECT_LT((arc.back() - to).norm(), 1e-9);
    double chords = 0.0;
    for (size_t i = 0; i < arc.size(); ++i) {
      EXPECT_NEAR(std::hypot(arc[i].x() - axis_x, arc[i].y()), kRadius, 1e-12);
      if (i > 0) chords += (arc[i] - arc[i - 1]).norm();
    }
    EXPECT_LE(chords, arc_length * (1 + 1e-12));
    EXPECT_GE(chords, arc_length * (1 - 3.2e-4));
  };
  check_arc(result.arc_points, result.p_WT1, result.p_WT2, 0.0, result.arc_length);
  check_arc(result.second_arc_points, result.p_WT3, result.p_WT4, d, result.second_arc_length);
  // Without the option, nothing is sampled.
  const WrapResult plain = obstacle.Wrap(p, s, At(Transform::Translation(Vec3(d, 0.0, 0.0))));
  EXPECT_TRUE(plain.arc_points.empty() && plain.second_arc_points.empty());
}

// U right-handed, V left-handed: the path goes under U and over V, crossing between them along
// the inner tangent through the midpoint M = (d / 2, 0), which touches each circle acos(r / m)
// from the x axis (m = d / 2). P and S are mirror images through M.
TEST(WrapDoubleCylinderObstTest, BothEngagedAlongTheCrossingTangentInOnePlane) {
  const double d = 0.1, a = 0.05, b = 0.01, m = d / 2;
  const WrapDoubleCylinderObst obstacle(kRadius, Direction::kRightHand, kRadius,
                                        Direction::kLeftHand);
  const Vec3 p(-a, -b, 0.0), s(d + a, b, 0.0);
  const double dp = std::hypot(a, b);
  const double q_angle = std::atan2(-b, -a) + std::acos(kRadius / dp);
  const double cross_angle = -std::acos(kRadius / m);  // where the crossing line leaves U
  const double arc_angle = cross_angle - q_angle;
  ASSERT_GT(arc_angle, 0.0);
  const double expected = 2 * (std::sqrt(dp * dp - kRadius * kRadius) + kRadius * arc_angle +
                               std::sqrt(m * m - kRadius * kRadius));
  const WrapResult result = obstacle.Wrap(p, s, At(Transform::Translation(Vec3(d, 0.0, 0.0))));
  ASSERT_TRUE(result.on_first && result.on_second);
  EXPECT_NEAR(PathLength(p, s, result), expected, 1e-12);
  std::cout << "crossing tangent: length error " << PathLength(p, s, result) - expected << " m\n";
  const Vec3 leaves_u(kRadius * std::cos(cross_angle), kRadius * std::sin(cross_angle), 0.0);
  EXPECT_LT((result.p_WT2 - leaves_u).norm(), 1e-11);
  EXPECT_LT((result.p_WT3 - (Vec3(d, 0.0, 0.0) - leaves_u)).norm(), 1e-11);
}

// P rises along x = -a toward the line of the cylinders from below (the side both wrap
// directions pass): first the segment clears both, then it touches one, then both. A path's
// length is 1-Lipschitz in its end point, so no step may change it by more than the step.
TEST(WrapDoubleCylinderObstTest, LengthIsContinuousAsTheCylindersEngage) {
  const double d = 0.1;
  const WrapDoubleCylinderObst obstacle(kRadius, Direction::kRightHand, kRadius,
                                        Direction::kRightHand);
  const WrapOptions options = At(Transform::Translation(Vec3(d, 0.0, 0.0)));
  const Vec3 s(d + 0.05, -0.01, 0.0);
  const int steps = 20000;
  const Vec3 from(-0.05, -0.1, 0.0), to(-0.05, -0.01, 0.0);
  const double step = (to - from).norm() / steps;
  double previous = 0.0;
  int none = 0, one = 0, both = 0;
  for (int i = 0; i <= steps; ++i) {
    const Vec3 p = from + (to - from) * (static_cast<double>(i) / steps);
    const WrapResult result = obstacle.Wrap(p, s, options);
    const double length = PathLength(p, s, result);
    if (i > 0) {
      EXPECT_LE(std::abs(length - previous), step + 1e-12) << "at step " << i;
    }
    previous = length;
    (result.on_first && result.on_second   ? both
     : result.on_first || result.on_second ? one
                                           : none)++;
  }
  std::cout << "steps over neither cylinder " << none << ", one " << one << ", both " << both
            << "\n";
  EXPECT_GT(none, 0);
  EXPECT_GT(one, 0);
  EXPECT_GT(both, 0);
}

TEST(WrapDoubleCylinderObstTest, RadiiMustBePositive) {
  EXPECT_THROW(WrapDoubleCylinderObst(-0.01, Direction::kRightHand, 0.02, Direction::kLeftHand),
               Error);
  EXPECT_THROW(WrapDoubleCylinderObst(0.01, Direction::kRightHand, 0.0, Direction::kLeftHand),
               Error);
}

}  // namespace
}  // namespace sinew::paths

// WrapDoubleCylinderObst in a model (tests/data/sinew/double_cylinder.osim): the reader's
// properties, the path's tangent points on the right bodies (U's on upper, V's on lower), a
// length continuous as the elbow flexes and the cylinders engage, and moment arms, lengthening
// speeds and generalized forces that are the derivatives of the length.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/io/osim_reader.h>
#include <sinew/kinematics/forward_kinematics.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "paths/path_derivative_check.h"
#include "paths/path_test_util.h"

namespace sinew::paths {
namespace {

using testing::PathModel;

const std::string kModel = testing::kDataDir + "/sinew/double_cylinder.osim";

TEST(WrapDoubleCylinderModelTest, ReadsTheVCylinderAndItsDirections) {
  const PathModel m(kModel);
  const int upper = m.spec.FindBody("upper"), lower = m.spec.FindBody("lower");
  const auto& wraps = m.spec.bodies[static_cast<size_t>(upper)].wrap_objects;
  ASSERT_EQ(wraps.size(), 2u);
  EXPECT_EQ(wraps[0].second_body, lower);
  EXPECT_TRUE(wraps[0].X_BV.p.isApprox(Vec3(0.0, -0.05, 0.0)));
  EXPECT_EQ(wraps[0].dimensions.at("radiusUcyl"), std::vector<double>{0.02});
  EXPECT_EQ(wraps[0].dimensions.at("wrap_vcyl_direction"), std::vector<double>{1.0});
  EXPECT_EQ(wraps[1].dimensions.at("wrap_ucyl_direction"), std::vector<double>{-1.0});
  EXPECT_EQ(wraps[1].dimensions.at("wrap_vcyl_direction"), std::vector<double>{-1.0});
  // Body-fixed x then y: V's z axis in lower is R_x(0.3) R_y(0.2) z.
  const Vec3 z_axis = wraps[1].X_BV.R.col(2);
  EXPECT_TRUE(z_axis.isApprox(
      Vec3(std::sin(0.2), -std::sin(0.3) * std::cos(0.2), std::cos(0.3) * std::cos(0.2)), 1e-15));
  EXPECT_FALSE(wraps[1].dimensions.contains("translationVcyl"));
}

// Which cylinders the path goes over, from its tangent points: U's lie on upper, V's on lower.
struct Over {
  bool u = false, v = false;
};
Over WhichCylinders(const PathModel& m, const PathState& state) {
  Over over;
  for (const PathPointState& point : state.points) {
    if (point.wrap < 0) continue;
    (point.body == m.spec.FindBody("upper") ? over.u : over.v) = true;
  }
  return over;
}

// How far beyond U's radius (first) and V's (second) the whole line through the path's two
// points passes from each axis, in that cylinder's cross-section: OpenSim's tests of whether a
// cylinder engages when the path first meets it.
std::array<double, 2> LineClearances(const PathModel& m, int path, const std::vector<double>& q) {
  const GeometryPath& g = m.paths.paths()[static_cast<size_t>(path)];
  std::vector<Transform> X_GB(static_cast<size_t>(m.tree.num_bodies()));
  kinematics::CalcBodyPoses(m.tree, q, X_GB);
  const PathWrap& wrap = g.wraps()[0];
  const auto& object = m.spec.bodies[static_cast<size_t>(wrap.body)].wrap_objects;
  const double radii[2] = {object[0].dimensions.at("radiusUcyl")[0],
                           object[0].dimensions.at("radiusVcyl")[0]};
  const Transform X_GC[2] = {X_GB[static_cast<size_t>(wrap.body)] * wrap.X_BW,
                             X_GB[static_cast<size_t>(wrap.second_body)] * wrap.X_BV};
  std::array<double, 2> clearance{};
  for (int c = 0; c < 2; ++c) {
    Eigen::Vector2d p[2];
    for (int k = 0; k < 2; ++k) {
      const PathPoint& point = g.points()[static_cast<size_t>(k)];
      const Vec3 p_G = X_GB[static_cast<size_t>(point.body)] * point.CalcLocationInBody(q);
      p[k] = (X_GC[c].Inverse() * p_G).head<2>();
    }
    const double cross = p[0].x() * p[1].y() - p[0].y() * p[1].x();
    clearance[static_cast<size_t>(c)] = std::abs(cross) / (p[1] - p[0]).norm() - radii[c];
  }
  return clearance;
}

TEST(WrapDoubleCylinderModelTest, LengthIsContinuousAsTheElbowFlexesUntilTheLinesClear) {
  const PathModel m(kModel);
  const int q2 = m.spec.FindCoordinate("q2");
  for (const char* name : {"ext", "ext_tilted"}) {
    const int path = m.FindPath(name);
    ASSERT_GE(path, 0);
    std::vector<double> q = m.tree.default_q();
    // A path's length is 1-Lipschitz in each of its points and obstacles' positions; turning
    // the lower link by dq moves its points (S, V's axis and tangent points, all within 0.15 m
    // of the elbow) by at most 0.15 dq each, so no step may change the length by more than
    // 0.3 dq. The one exception is OpenSim's: where the whole line through the path's points
    // stops passing within the radius of the cylinder it meets first (on the far side of a
    // deep wrap), the path snaps straight (docs/wrapping.md); every jump must be there.
    const double step = 1e-4, bound = 0.3 * step;
    double previous = 0.0;
    std::array<double, 2> previous_line{};
    int none = 0, u_only = 0, v_only = 0, both = 0, snaps = 0;
    for (int i = 0; i <= 37000; ++i) {
      q[static_cast<size_t>(q2)] = -1.5 + i * step;
      const PathState state = m.CalcState(path, q);
      const std::array<double, 2> line = LineClearances(m, path, q);
      if (i > 0 && std::abs(state.length - previous) > bound) {
        ++snaps;
        EXPECT_TRUE(line[0] * previous_line[0] <= 0.0 || line[1] * previous_line[1] <= 0.0)
            << name << " jumps by " << state.length - previous
            << " m at q2 = " << q[static_cast<size_t>(q2)];
        std::cout << name << ": snaps by " << state.length - previous
                  << " m at q2 = " << q[static_cast<size_t>(q2)] << "\n";
      }
      previous = state.length;
      previous_line = line;
      const Over over = WhichCylinders(m, state);
      (over.u ? (over.v ? both : u_only) : (over.v ? v_only : none))++;
    }
    std::cout << name << ": steps over neither cylinder " << none << ", U only " << u_only
              << ", V only " << v_only << ", both " << both << "\n";
    EXPECT_GT(none, 0) << name;
    EXPECT_GT(both, 0) << name;
    EXPECT_LE(snaps, 2) << name;
  }
}

// Drawing: with arc points asked for, each arc a tangent point starts (T1 over U, T3 over V)
// runs from it to the next tangent point, in ground, and its chords add up to the arc's length
// within the 5 degree sampling's bound (a^2 / 24 relative, 3.2e-4).
TEST(WrapDoubleCylinderModelTest, BothArcsAreDrawnBetweenTheirTangentPoints) {
  const PathModel m(kModel);
  const int q2 = m.spec.FindCoordinate("q2");
  for (const char* name : {"ext", "ext_tilted"}) {
    const int path = m.FindPath(name);
    ASSERT_GE(path, 0);
    std::vector<double> q = m.tree.default_q();
    std::vector<Transform> X_GB(static_cast<size_t>(m.tree.num_bodies()));
    PathState state;
    int arcs_checked = 0, poses_with_both = 0;
    for (int i = 0; i <= 370; ++i) {
      q[static_cast<size_t>(q2)] = -1.5 + i * 0.01;
      kinematics::CalcBodyPoses(m.tree, q, X_GB);
      m.paths.paths()[static_cast<size_t>(path)].CalcState(q, X_GB, state, true);
      const Over over = WhichCylinders(m, state);
      poses_with_both += over.u && over.v ? 1 : 0;
      for (size_t k = 0; k + 1 < state.points.size(); ++k) {
        const PathPointState& point = state.points[k];
        if (point.wrap < 0 || point.arc_length_to_next < 0.0) continue;
        const std::vector<Vec3>& arc =
            state.arc_G[static_cast<size_t>(PathState::ArcIndex(point.wrap, point.tangent))];
        ASSERT_GE(arc.size(), 2u) << name << " at q2 = " << q[static_cast<size_t>(q2)];
        EXPECT_LT((arc.front() - point.p_GP).norm(), 1e-12);
        EXPECT_LT((arc.back() - state.points[k + 1].p_GP).norm(), 1e-9);
        double chords = 0.0;
        for (size_t j = 1; j < arc.size(); ++j) chords += (arc[j] - arc[j - 1]).norm();
        EXPECT_LE(chords, point.arc_length_to_next * (1 + 1e-12) + 1e-15);
        EXPECT_GE(chords, point.arc_length_to_next * (1 - 3.2e-4));
        ++arcs_checked;
      }
    }
    EXPECT_GT(poses_with_both, 0) << name;
    std::cout << name << ": " << arcs_checked << " arcs checked, " << poses_with_both
              << " poses over both cylinders\n";
  }
}

TEST(WrapDoubleCylinderModelTest, MomentArmsSpeedsAndForcesAreDerivativesOfLength) {
  const PathModel m(kModel);
  // The wrapped path is the shortest over both cylinders (each piece is the unrolled straight
  // line over its cylinder), so the analytic values are the derivatives of the length wrapped
  // afresh too.
  std::vector<std::vector<double>> poses = testing::MakePoses(m, 40);
  int wrapped_both = 0;
  for (const auto& q : poses) {
    for (size_t p = 0; p < m.paths.paths().size(); ++p) {
      const Over over = WhichCylinders(m, m.CalcState(static_cast<int>(p), q));
      wrapped_both += over.u && over.v ? 1 : 0;
    }
  }
  EXPECT_GT(wrapped_both, 10);
  testing::CheckMomentArmsAndSpeeds(m, "double_cylinder", poses, true);
  EXPECT_GT(testing::CheckGeneralizedForces(m, poses), 20);
}

// OpenSim reports a wrap over neither cylinder as a wrap adding no length, and keeps the
// segment of its range whose wrap adds least: with a via point that makes a first segment
// clear of both cylinders, the extensor stays straight even where its second segment would
// wrap; restricted to that second segment by its range, it wraps (docs/wrapping.md).
TEST(WrapDoubleCylinderModelTest, ARangeOfSeveralSegmentsWrapsOnlyIfEverySegmentEngages) {
  std::ifstream in(kModel);
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::string text = buffer.str();
  const std::string origin_end = "<location>-0.03 -0.1 0</location>\n                </PathPoint>";
  ASSERT_NE(text.find(origin_end), std::string::npos);
  text.insert(text.find(origin_end) + origin_end.size(),
              "<PathPoint name=\"via\"><socket_parent_frame>/ground</socket_parent_frame>"
              "<location>-0.03 -0.15 0</location></PathPoint>");
  const std::string with_via = (std::filesystem::path(::testing::TempDir()) / "via.osim").string();
  std::ofstream(with_via) << text;
  const std::string range = "<range>-1 -1</range>";
  text.replace(text.find(range), range.size(), "<range>2 3</range>");
  const std::string second_only =
      (std::filesystem::path(::testing::TempDir()) / "via_range.osim").string();
  std::ofstream(second_only) << text;

  const PathModel whole(with_via), second(second_only);
  std::vector<double> q = whole.tree.default_q();
  q[static_cast<size_t>(whole.spec.FindCoordinate("q2"))] = 0.5;
  const int path = whole.FindPath("ext");
  const PathState straight = whole.CalcState(path, q);
  ASSERT_EQ(straight.points.size(), 3u);  // origin, via, insertion: no tangent points
  std::vector<Transform> X_GB(static_cast<size_t>(whole.tree.num_bodies()));
  kinematics::CalcBodyPoses(whole.tree, q, X_GB);
  const Vec3 origin(-0.03, -0.1, 0.0), via(-0.03, -0.15, 0.0);
  const Vec3 insertion =
      X_GB[static_cast<size_t>(whole.spec.FindBody("lower"))] * Vec3(-0.015, -0.12, 0.0);
  EXPECT_NEAR(straight.length, (via - origin).norm() + (insertion - via).norm(), 1e-15);
  const PathState wrapped = second.CalcState(second.FindPath("ext"), q);
  const Over over = WhichCylinders(second, wrapped);
  EXPECT_TRUE(over.u || over.v);
  EXPECT_GT(wrapped.length, straight.length + 1e-3);
}

TEST(WrapDoubleCylinderModelTest, AnUnknownVBodyIsAnErrorNamingTheWrapObject) {
  std::ifstream in(kModel);
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::string text = buffer.str();
  const std::string good = "<wrapVcylHomeBodyName>lower</wrapVcylHomeBodyName>";
  text.replace(text.find(good), good.size(),
               "<wrapVcylHomeBodyName>forearm</wrapVcylHomeBodyName>");
  try {
    io::ReadOsimString(text, "double_cylinder.osim");
    ADD_FAILURE() << "no error";
  } catch (const Error& error) {
    const std::string what = error.what();
    EXPECT_NE(what.find("double_cylinder.osim:"), std::string::npos) << what;
    EXPECT_NE(what.find("/bodyset/upper/wrapobjectset/elbow_wrap"), std::string::npos) << what;
    EXPECT_NE(what.find("wrapVcylHomeBodyName 'forearm' is not a body"), std::string::npos) << what;
  }
  // A negative radius: the model reads, and the path refuses to wrap over the object.
  text = buffer.str();
  const std::string radius = "<radiusUcyl>0.02</radiusUcyl>";
  text.replace(text.find(radius), radius.size(), "<radiusUcyl>-0.02</radiusUcyl>");
  const model::ModelSpec spec = io::ReadOsimString(text, "double_cylinder.osim");
  try {
    PathSet paths(spec);
    ADD_FAILURE() << "no error";
  } catch (const Error& error) {
    const std::string what = error.what();
    EXPECT_NE(what.find("elbow_wrap"), std::string::npos) << what;
    EXPECT_NE(what.find("radiusUcyl must be positive and finite (got -0.02)"), std::string::npos)
        << what;
  }
}

}  // namespace
}  // namespace sinew::paths

// How a wrapping surface plugs into a path (the contract of wrap_surface.h), with a stand-in
// surface whose tangent points are fixed in its frame: the path goes P-T1, over the arc, T2-S,
// its length and derivatives follow, and the omission list forgets the wrap once connected.
#include <gtest/gtest.h>
#include <sinew/paths/path_analysis.h>

#include <cmath>

#include "paths/path_test_util.h"

namespace sinew::paths {
namespace {

using testing::kDataDir;
using testing::PathModel;

// Wraps every segment: tangent points at fixed places in W, a fixed arc length. Not a shape:
// only the plumbing is under test here.
class FixedTangentsSurface final : public WrapSurface {
 public:
  WrapResult Wrap(const Vec3& /*p_WP*/, const Vec3& /*p_WS*/,
                  const WrapOptions& /*options*/) const override {
    WrapResult result;
    result.wrapped = true;
    result.p_WT1 = Vec3(0.01, 0.02, 0.0);
    result.p_WT2 = Vec3(-0.01, 0.02, 0.0);
    result.arc_length = 0.03;
    return result;
  }
};

const std::string kArm26 = kDataDir + "/MyoHub/myoconverter/models/osim/Arm26/arm26.osim";

TEST(WrapPlugTest, UnconnectedWrapsAreListedByPathAndObject) {
  PathModel m(kArm26);
  // Every arm26 wrap object is of a supported type, so connected: take one away.
  EXPECT_TRUE(m.paths.ListOmissions(m.spec).empty());
  m.paths.mutable_paths().front().ConnectWrapSurface(0, nullptr);
  const Diagnostics omissions = m.paths.ListOmissions(m.spec);
  ASSERT_FALSE(omissions.empty());
  const std::string first = omissions.front().Format();
  EXPECT_NE(first.find("arm26.osim:"), std::string::npos) << first;
  EXPECT_NE(first.find("/forceset/"), std::string::npos) << first;
  EXPECT_NE(first.find("is not applied yet"), std::string::npos) << first;
}

TEST(WrapPlugTest, ConnectedSurfaceReplacesTheBestSegmentByTangentsAndArc) {
  PathModel m(kArm26);
  const int p = m.FindPath("TRIlong");
  ASSERT_GE(p, 0);
  GeometryPath& path = m.paths.mutable_paths()[static_cast<size_t>(p)];
  ASSERT_FALSE(path.wraps().empty());
  const std::vector<double> q = m.tree.default_q();
  for (size_t w = 0; w < path.wraps().size(); ++w) {
    path.ConnectWrapSurface(static_cast<int>(w), nullptr);
  }
  const PathState straight = m.CalcState(p, q);
  const size_t omitted_unconnected = m.paths.ListOmissions(m.spec).size();
  path.ConnectWrapSurface(0, std::make_shared<FixedTangentsSurface>());
  const PathState wrapped = m.CalcState(p, q);
  ASSERT_EQ(wrapped.points.size(), straight.points.size() + 2);
  // Find T1: the point with an arc to the next.
  size_t t1 = 0;
  while (t1 < wrapped.points.size() && wrapped.points[t1].arc_length_to_next < 0) ++t1;
  ASSERT_LT(t1 + 1, wrapped.points.size());
  EXPECT_EQ(wrapped.points[t1].wrap, 0);
  EXPECT_EQ(wrapped.points[t1 + 1].wrap, 0);
  // The length is the straight length with segment P-S replaced by P-T1 + arc + T2-S.
  const Vec3 P = wrapped.points[t1 - 1].p_GP, T1 = wrapped.points[t1].p_GP,
             T2 = wrapped.points[t1 + 1].p_GP, S = wrapped.points[t1 + 2].p_GP;
  const double expected =
      straight.length - (S - P).norm() + (T1 - P).norm() + 0.03 + (S - T2).norm();
  EXPECT_NEAR(wrapped.length, expected, 1e-14);
  EXPECT_EQ(m.paths.ListOmissions(m.spec).size() + 1, omitted_unconnected);
  // Tangent points fixed on the surface's body: the moment arms are still -dL/dq.
  std::vector<int> all(q.size());
  for (size_t c = 0; c < all.size(); ++c) all[c] = static_cast<int>(c);
  PathAnalysis analysis(m.spec, m.tree, m.couplers, m.paths, all);
  analysis.Calc(q, std::vector<double>(q.size(), 0.0));
  for (size_t k = 0; k < q.size(); ++k) {
    std::vector<double> plus = q, minus = q;
    plus[k] += 1e-5;
    minus[k] -= 1e-5;
    const double dL = (m.CalcLength(p, plus) - m.CalcLength(p, minus)) / 2e-5;
    EXPECT_NEAR(analysis.moment_arm(k, static_cast<size_t>(p)), -dL, 1e-8)
        << m.spec.coordinates[k].name;
  }
}

TEST(PathErrorsTest, APathWithOnePointIsRefusedWithFileLineAndComponent) {
  model::ModelSpec spec = io::ReadOsim(kArm26);
  model::ForceSpec& force = spec.forces.front();
  ASSERT_TRUE(force.geometry_path);
  force.geometry_path->points.resize(1);
  try {
    PathSet paths(spec);
    FAIL() << "a one-point path was accepted";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("arm26.osim:"), std::string::npos) << message;
    EXPECT_NE(message.find(force.path), std::string::npos) << message;
    EXPECT_NE(message.find("at least two points"), std::string::npos) << message;
  }
}

TEST(PathErrorsTest, APathWhoseActivePointsRunOutIsAnErrorNamingIt) {
  const PathModel m(kDataDir +
                    "/opensim-org/opensim-core/OpenSim/Moco/Test/walk_gait1018_subject01.osim");
  model::ModelSpec spec = m.spec;
  // Make every point of the first path conditional on a range its coordinate is never in.
  model::ForceSpec& force = spec.forces.front();
  for (model::PathPointSpec& point : force.geometry_path->points) {
    point.type = "ConditionalPathPoint";
    point.coordinate = 0;
    point.range_min = 100.0;
    point.range_max = 101.0;
  }
  const PathSet paths(spec);
  std::vector<Transform> X_GB(static_cast<size_t>(m.tree.num_bodies()));
  const std::vector<double> q = m.tree.default_q();
  kinematics::CalcBodyPoses(m.tree, q, X_GB);
  PathState state;
  try {
    paths.paths().front().CalcState(q, X_GB, state);
    FAIL() << "a path without active points was computed";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(force.path), std::string::npos) << message;
    EXPECT_NE(message.find("a path needs two"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace sinew::paths

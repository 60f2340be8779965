// OpenSim's moment arms where tangent points are stale (several wrap objects, docs/paths.md):
// PathAnalysis::opensim_moment_arm against an independent evaluation of OpenSim's rule, and
// PathAnalysis::moment_arm (what Sinew's dynamics use) against the derivative of the length.
#include <gtest/gtest.h>
#include <sinew/kinematics/forward_kinematics.h>
#include <sinew/paths/path_analysis.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "paths/path_derivative_check.h"
#include "paths/path_test_util.h"

namespace sinew::paths {
namespace {

using testing::Differentiate;
using testing::Difference;
using testing::kDataDir;
using testing::kRounding;
using testing::PathModel;

// OpenSim's rule written out: along each straight segment between points of different bodies,
// the direction from the locations as read (the state's p_GP, stale ones included), times the
// relative motion of the points where the forces are applied (a tangent point where the last
// pass placed it, p_BP_placed), each carried by its body as q_c moves. Minus the derivative of
// sum e . (p_b(q) - p_a(q)) with the directions held.
Difference OpenSimRule(const PathModel& m, const PathState& state, std::vector<double> q, int c) {
  const auto applied = [&](double h) {
    std::vector<double> moved = q;
    moved[static_cast<size_t>(c)] += h;
    std::vector<Transform> X_GB(static_cast<size_t>(m.tree.num_bodies()));
    kinematics::CalcBodyPoses(m.tree, moved, X_GB);
    double sum = 0.0;
    for (size_t i = 0; i + 1 < state.points.size(); ++i) {
      const PathPointState& a = state.points[i];
      const PathPointState& b = state.points[i + 1];
      if (a.body == b.body) continue;
      const Vec3 e = (b.p_GP - a.p_GP).normalized();
      const Vec3 p_a = a.wrap >= 0 ? a.p_BP_placed : a.p_BP;
      const Vec3 p_b = b.wrap >= 0 ? b.p_BP_placed : b.p_BP;
      sum += e.dot(X_GB[static_cast<size_t>(b.body)] * p_b - X_GB[static_cast<size_t>(a.body)] * p_a);
    }
    return sum;
  };
  const Difference d = Differentiate(applied);
  return {-d.value, d.error + kRounding};
}

// arm26's TRIlong (three wrap objects) swept about the shoulder at MyoConverter's reference
// poses (25 values over the range, elbow at its default): where tangent points are stale,
// OpenSim's moment arm is its rule (directions as read, forces where the points are now), while
// Sinew's moment_arm is -dL/dq of the path through the points as read (its length); the two
// differ there by up to 7.9e-3 m, which is how far Sinew's moment_arm is off OpenSim's
// reference (MyoConverterReferenceTest compares opensim_moment_arm). Elsewhere they are the
// same number.
TEST(OpenSimMomentArmTest, StaleTangentPointsPullFromWhereTheyWereReadAtWhereTheyAreNow) {
  const PathModel m(kDataDir + "/MyoHub/myoconverter/models/osim/Arm26/arm26.osim",
                    CylinderRefinement::kSeveralWrapsOpenSim44);
  const int path = m.FindPath("TRIlong");
  const int shoulder = m.spec.FindCoordinate("r_shoulder_elev");
  ASSERT_GE(path, 0);
  ASSERT_GE(shoulder, 0);
  PathAnalysis analysis(m.spec, m.tree, m.couplers, m.paths, {shoulder});
  int stale = 0;
  double worst_apart = 0.0;
  for (int step = 0; step <= 24; ++step) {
    std::vector<double> q = m.tree.default_q();
    q[static_cast<size_t>(shoulder)] = -1.5708 + 4.7124 * step / 24.0;
    const std::vector<double> u(q.size(), 0.0);
    analysis.Calc(q, u);
    const PathState state = m.CalcState(path, q);
    const double sinew = analysis.moment_arm(0, static_cast<size_t>(path));
    const double opensim = analysis.opensim_moment_arm(0, static_cast<size_t>(path));
    const std::string at = "shoulder at " + std::to_string(q[static_cast<size_t>(shoulder)]);
    // Sinew's: -dL/dq of the path through the points as read, the tangent points carried by
    // their bodies (what its generalized force is; PathDerivativesTest checks every path).
    const Difference through = Differentiate([&](double h) {
      std::vector<double> moved = q;
      moved[static_cast<size_t>(shoulder)] += h;
      return m.CalcLengthThrough(path, moved, state);
    });
    EXPECT_NEAR(sinew, -through.value, through.error + kRounding) << at;
    if (state.stale_tangent_points == 0) {
      EXPECT_EQ(opensim, sinew) << at;
      continue;
    }
    ++stale;
    const Difference rule = OpenSimRule(m, state, q, shoulder);
    EXPECT_NEAR(opensim, rule.value, rule.error) << at;
    worst_apart = std::max(worst_apart, std::abs(opensim - sinew));
  }
  std::cout << stale << " of 25 poses with stale tangent points; OpenSim's moment arm differs "
            << "from -dL/dq there by up to " << worst_apart << " m\n";
  EXPECT_GE(stale, 5);
  EXPECT_GT(worst_apart, 5e-3);
}

}  // namespace
}  // namespace sinew::paths

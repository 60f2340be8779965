// OpenSim's rules for applying wrap objects to a path (GeometryPath::applyWrapObjects), with
// stand-in surfaces that record what they are offered: `range`, inactive objects, the first
// mandatory wrap, the least lengthening among plain wraps; and, with arm26's real surfaces, the
// length along a fine elbow sweep, continuous as the wraps engage and disengage; and which
// OpenSim version's cylinder rule a path follows (CylinderRefinement).
#include <gtest/gtest.h>
#include <sinew/paths/path_analysis.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "paths/path_test_util.h"

namespace sinew::paths {
namespace {

using testing::kDataDir;
using testing::PathModel;

const std::string kArm26 = kDataDir + "/MyoHub/myoconverter/models/osim/Arm26/arm26.osim";

// Wraps every segment it is offered (mandatory or plain) with tangent points a tenth of the way
// from each end and an arc as long as the chord plus `extra(call)`, recording the segments.
class RecordingSurface final : public WrapSurface {
 public:
  RecordingSurface(bool mandatory, std::vector<double> extra)
      : mandatory_(mandatory), extra_(std::move(extra)) {}
  WrapResult Wrap(const Vec3& p_WP, const Vec3& p_WS, const WrapOptions&) const override {
    WrapResult result;
    result.wrapped = true;
    result.mandatory = mandatory_;
    result.p_WT1 = p_WP + 0.1 * (p_WS - p_WP);
    result.p_WT2 = p_WP + 0.9 * (p_WS - p_WP);
    const size_t call = offered.size();
    result.arc_length = (result.p_WT2 - result.p_WT1).norm() + extra_.at(call % extra_.size());
    offered.emplace_back(p_WP, p_WS);
    return result;
  }
  mutable std::vector<std::pair<Vec3, Vec3>> offered;

 private:
  bool mandatory_;
  std::vector<double> extra_;
};

// arm26 with BICshort's path (6 points, no wraps of its own) given one PathWrap over the
// humerus's TRI cylinder, with `range`; `active` sets the wrap object's flag.
struct OneWrapModel {
  OneWrapModel(std::array<int, 2> range, bool active) : m(Build(range, active)) {
    path = m.FindPath("BICshort");
  }
  static PathModel Build(std::array<int, 2> range, bool active) {
    PathModel built(kArm26);
    for (model::BodySpec& body : built.spec.bodies) {
      for (model::WrapObjectSpec& w : body.wrap_objects) {
        if (w.name == "TRI") w.active = active;
      }
    }
    for (model::ForceSpec& force : built.spec.forces) {
      if (force.name == "BICshort") force.geometry_path->wraps = {{"TRI", "hybrid", range}};
    }
    built.paths = PathSet(built.spec);
    return built;
  }
  PathModel m;
  int path = -1;
};

// Indices of the path points (not tangent points) either side of each tangent-point pair.
std::vector<std::pair<int, int>> WrappedSegments(const PathState& state) {
  std::vector<std::pair<int, int>> out;
  for (size_t k = 1; k + 2 < state.points.size(); ++k) {
    if (state.points[k].arc_length_to_next >= 0.0) {
      out.emplace_back(state.points[k - 1].point, state.points[k + 2].point);
    }
  }
  return out;
}

TEST(PathWrapRulesTest, OnlySegmentsWithinTheRangeAreOffered) {
  OneWrapModel one({3, 5}, true);
  auto surface = std::make_shared<RecordingSurface>(false, std::vector<double>{0.01});
  one.m.paths.mutable_paths()[static_cast<size_t>(one.path)].ConnectWrapSurface(0, surface);
  const std::vector<double> q = one.m.tree.default_q();
  const PathState state = one.m.CalcState(one.path, q);
  // Points 3 to 5 (1-based): segments 3-4 and 4-5, i.e. 0-based points 2-3 and 3-4.
  ASSERT_EQ(surface->offered.size(), 2u);
  const PathState straight = OneWrapModel({3, 5}, false).m.CalcState(one.path, q);
  EXPECT_EQ(WrappedSegments(state), (std::vector<std::pair<int, int>>{{2, 3}}));
  // Equal extra length: the first of the equally good plain wraps is kept.
  EXPECT_NEAR(state.length, straight.length + 0.01, 1e-12);
}

TEST(PathWrapRulesTest, AnInactiveObjectDoesNotWrap) {
  OneWrapModel one({-1, -1}, false);
  auto surface = std::make_shared<RecordingSurface>(true, std::vector<double>{0.01});
  one.m.paths.mutable_paths()[static_cast<size_t>(one.path)].ConnectWrapSurface(0, surface);
  const PathState state = one.m.CalcState(one.path, one.m.tree.default_q());
  EXPECT_TRUE(surface->offered.empty());
  EXPECT_TRUE(WrappedSegments(state).empty());
}

TEST(PathWrapRulesTest, TheFirstMandatoryWrapIsTakenAtOnce) {
  OneWrapModel one({-1, -1}, true);
  auto surface = std::make_shared<RecordingSurface>(true, std::vector<double>{0.05, 0.0});
  one.m.paths.mutable_paths()[static_cast<size_t>(one.path)].ConnectWrapSurface(0, surface);
  const PathState state = one.m.CalcState(one.path, one.m.tree.default_q());
  EXPECT_EQ(surface->offered.size(), 1u);
  EXPECT_EQ(WrappedSegments(state), (std::vector<std::pair<int, int>>{{0, 1}}));
}

TEST(PathWrapRulesTest, AmongPlainWrapsTheLeastLengtheningIsKept) {
  OneWrapModel one({-1, -1}, true);
  // Five segments offered in order; the fourth adds least.
  auto surface = std::make_shared<RecordingSurface>(
      false, std::vector<double>{0.05, 0.04, 0.03, 0.001, 0.02});
  one.m.paths.mutable_paths()[static_cast<size_t>(one.path)].ConnectWrapSurface(0, surface);
  const PathState state = one.m.CalcState(one.path, one.m.tree.default_q());
  EXPECT_EQ(surface->offered.size(), 5u);
  EXPECT_EQ(WrappedSegments(state), (std::vector<std::pair<int, int>>{{3, 4}}));
}

// Along a sweep of the elbow in steps h, each step changes every arm26 path's length by no more
// than h times the larger moment arm at its ends plus the second-order term (h^2 / 2 times a
// curvature bound of 1 m/rad^2, far above any muscle's): a jump where a wrap engages or
// disengages would break this. The sweep must see each surface engage and disengage.
TEST(PathWrapRulesTest, LengthsAreContinuousAsWrapsEngageAndDisengage) {
  const PathModel m(kArm26);
  const int elbow = m.spec.FindCoordinate("r_elbow_flex");
  ASSERT_GE(elbow, 0);
  PathAnalysis analysis(m.spec, m.tree, m.couplers, m.paths, {elbow});
  const double h = 1e-3;
  std::vector<double> q = m.tree.default_q();
  const size_t num_paths = m.paths.paths().size();
  std::vector<double> previous_length(num_paths), previous_arm(num_paths);
  std::vector<int> changes(num_paths, 0);
  std::vector<bool> previous_wrapped(num_paths);
  double worst = 0.0;
  for (int i = 0; i * h <= 2.2; ++i) {
    q[static_cast<size_t>(elbow)] = i * h;
    analysis.Calc(q, std::vector<double>(q.size(), 0.0));
    for (size_t p = 0; p < num_paths; ++p) {
      const bool wrapped = PathModel::IsWrapped(m.CalcState(static_cast<int>(p), q));
      const double length = analysis.lengths()[p], arm = analysis.moment_arm(0, p);
      if (i > 0) {
        changes[p] += wrapped != previous_wrapped[p] ? 1 : 0;
        const double bound =
            h * std::max(std::abs(arm), std::abs(previous_arm[p])) + 0.5 * h * h;
        const double step = std::abs(length - previous_length[p]);
        worst = std::max(worst, step / bound);
        EXPECT_LE(step, bound) << m.paths.paths()[p].name() << " at " << i * h;
      }
      previous_length[p] = length;
      previous_arm[p] = arm;
      previous_wrapped[p] = wrapped;
    }
  }
  int engaging = 0;
  for (int c : changes) engaging += c > 0 ? 1 : 0;
  std::cout << engaging << " of " << num_paths
            << " paths engage or disengage a wrap along the sweep; worst step / bound " << worst
            << "\n";
  EXPECT_GE(engaging, 3);
}

// Hands every wrap on to `surface` with WrapOptions::single_wrap replaced by `single_wrap`,
// recording the value the path asked for.
class ForcedSingleWrapSurface final : public WrapSurface {
 public:
  ForcedSingleWrapSurface(std::shared_ptr<const WrapSurface> surface, bool single_wrap)
      : surface_(std::move(surface)), single_wrap_(single_wrap) {}
  WrapResult Wrap(const Vec3& p_WP, const Vec3& p_WS, const WrapOptions& options) const override {
    asked.push_back(options.single_wrap);
    WrapOptions forced = options;
    forced.single_wrap = single_wrap_;
    return surface_->Wrap(p_WP, p_WS, forced);
  }
  mutable std::vector<bool> asked;

 private:
  std::shared_ptr<const WrapSurface> surface_;
  bool single_wrap_;
};

// OpenSim's cylinder rule by version (docs/wrapping.md): OpenSim 4.4 and later refine a
// cylinder's tangent points only on paths with two or more wrap objects, every earlier version
// on every path. arm26's BRA (one wrap object, the elbow cylinder, wrapped at full extension)
// built with CylinderRefinement::kSeveralWrapsOpenSim44 asks its cylinder for a single wrap;
// built with kAlways it gets, bit for bit, what the cylinder gives when told to refine, and
// refining shortens it (the refinement takes out the kink between the straight segments and
// the helix). TRIlong's path (three wrap objects) is the same under both rules. OpenSim 4.4.1
// changed how the second tangent point is checked (kSeveralWraps): told to refine, BRA's
// cylinder then gives other tangent points.
TEST(PathWrapRulesTest, CylinderRefinementFollowsTheOpenSimVersionsRule) {
  const PathModel m(kArm26);
  const int elbow = m.spec.FindCoordinate("r_elbow_flex");
  ASSERT_GE(elbow, 0);
  std::vector<double> q = m.tree.default_q();
  q[static_cast<size_t>(elbow)] = 0.0;
  std::vector<Transform> X_GB(static_cast<size_t>(m.tree.num_bodies()));
  kinematics::CalcBodyPoses(m.tree, q, X_GB);
  auto state_of = [&](const std::string& name, CylinderRefinement refinement,
                      std::shared_ptr<ForcedSingleWrapSurface>* forced = nullptr) {
    for (const model::ForceSpec& force : m.spec.forces) {
      if (force.name != name) continue;
      GeometryPath path(m.spec, force, refinement);
      if (forced) {
        EXPECT_EQ(path.wraps().size(), 1u);
        *forced = std::make_shared<ForcedSingleWrapSurface>(path.wraps()[0].surface, false);
        path.ConnectWrapSurface(0, *forced);
      }
      PathState state;
      path.CalcState(q, X_GB, state);
      return state;
    }
    ADD_FAILURE() << name;
    return PathState();
  };
  std::shared_ptr<ForcedSingleWrapSurface> told_to_refine;
  const PathState since_4_4 =
      state_of("BRA", CylinderRefinement::kSeveralWrapsOpenSim44, &told_to_refine);
  const PathState before_4_4 = state_of("BRA", CylinderRefinement::kAlways);
  ASSERT_TRUE(PathModel::IsWrapped(since_4_4));
  ASSERT_TRUE(PathModel::IsWrapped(before_4_4));
  EXPECT_EQ(told_to_refine->asked, std::vector<bool>{true});
  EXPECT_EQ(before_4_4.length, since_4_4.length);
  ASSERT_EQ(before_4_4.points.size(), since_4_4.points.size());
  for (size_t i = 0; i < before_4_4.points.size(); ++i) {
    EXPECT_EQ(before_4_4.points[i].p_GP, since_4_4.points[i].p_GP) << i;
  }
  const PathState unrefined = state_of("BRA", CylinderRefinement::kSeveralWraps);
  std::printf("BRA at full elbow extension: %.10f m unrefined (OpenSim 4.4), %.10f m refined\n",
              unrefined.length, before_4_4.length);
  EXPECT_LT(before_4_4.length, unrefined.length);
  EXPECT_EQ(state_of("TRIlong", CylinderRefinement::kAlways).length,
            state_of("TRIlong", CylinderRefinement::kSeveralWrapsOpenSim44).length);
  // OpenSim 4.4.1's check of T2, told to refine: the same wrap, other tangent points.
  std::shared_ptr<ForcedSingleWrapSurface> told_to_refine_4_4_1;
  const PathState since_4_4_1 =
      state_of("BRA", CylinderRefinement::kSeveralWraps, &told_to_refine_4_4_1);
  ASSERT_EQ(since_4_4_1.points.size(), before_4_4.points.size());
  double moved = 0.0;
  for (size_t i = 0; i < before_4_4.points.size(); ++i) {
    moved = std::max(moved, (since_4_4_1.points[i].p_GP - before_4_4.points[i].p_GP).norm());
  }
  std::printf("BRA's tangent points refined as OpenSim 4.4.1 checks them: %.3g m away\n", moved);
  EXPECT_GT(moved, 1e-6);
}

}  // namespace
}  // namespace sinew::paths

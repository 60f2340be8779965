// The analytic derivatives of path length against central differences of the length itself,
// on models with conditional and moving path points and a coupler: moment arms (with coupled
// coordinates moving together), lengthening speeds, and the generalized force of a tension.
#include <gtest/gtest.h>
#include <sinew/paths/coupling_vector.h>
#include <sinew/paths/path_analysis.h>
#include <sinew/paths/path_loads.h>
#include <sinew/paths/wrap_cylinder.h>
#include <sinew/paths/wrap_sphere.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>

#include "paths/path_derivative_check.h"
#include "paths/path_test_util.h"

namespace sinew::paths {
namespace {

using testing::CheckMomentArmsAndSpeeds;
using testing::Difference;
using testing::Differentiate;
using testing::kDataDir;
using testing::kRounding;
using testing::MakePoses;
using testing::Move;
using testing::NearAConditionalLimit;
using testing::PathModel;

// arm26 at 13 poses: the worst |analytic - d/dq of the length wrapped afresh| on its wrapped
// paths (without stale tangent points) was 4.8e-4 m; twice that.
constexpr double kArm26Kink = 1e-3;

double CheckMomentArmsAndSpeeds(const std::string& file, int num_poses) {
  const PathModel m(file);
  return CheckMomentArmsAndSpeeds(m, file.substr(file.rfind('/') + 1), MakePoses(m, num_poses),
                                  false);
}

TEST(PathDerivativesTest, WalkGait1018MomentArmsAndSpeedsAreDerivativesOfLength) {
  CheckMomentArmsAndSpeeds(
      kDataDir + "/opensim-org/opensim-core/OpenSim/Moco/Test/walk_gait1018_subject01.osim", 8);
}

// leg6dof9musc (OpenSim 4 conversion by MyoConverter): conditional and moving points and a
// CoordinateCouplerConstraint.
TEST(PathDerivativesTest, Leg6Dof9MuscMomentArmsAndSpeedsAreDerivativesOfLength) {
  CheckMomentArmsAndSpeeds(
      kDataDir + "/MyoHub/myoconverter/models/osim/Leg6Dof9Musc/leg6dof9musc.osim", 8);
}

// Rajagopal2016: the patellae follow the knees through couplers, so a knee moment arm moves
// the patella along; the moving-point-free paths test the coupling vector alone. Its 46
// PathWraps over 40 cylinders wrap 75 path states at these poses: there OpenSim's cylinder
// construction is not the shortest path (docs/wrapping.md), and its moment arms, like Sinew's,
// are those of the tangent points carried by the bone; they differ from -dL/dq of the length
// wrapped afresh by 9.4e-4 m at most here (the refined construction's 0.1 degree kink times
// how fast the tangent points slide). Bounded at twice that. Path states with stale tangent
// points (OpenSim's cached ground locations over several passes, docs/paths.md) are reported
// apart: their length, as OpenSim's, is not the length of the path the moment arms are of.
TEST(PathDerivativesTest, Rajagopal2016MomentArmsFollowTheCoupledPatellae) {
  const double worst = CheckMomentArmsAndSpeeds(
      kDataDir + "/opensim-org/opensim-models/Models/Rajagopal/Rajagopal2016.osim", 2);
  EXPECT_LT(worst, 2e-3);
}

// The coupling vectors of every coordinate at once (one factorization shared by the free
// coordinates; PathAnalysis's way) equal those computed one at a time, locked coordinates
// (whose own lock is left out) included, at Rajagopal2016's poses.
TEST(PathDerivativesTest, CouplingVectorsAtOnceEqualOneAtATime) {
  const PathModel m(kDataDir + "/opensim-org/opensim-models/Models/Rajagopal/Rajagopal2016.osim");
  std::vector<int> all(m.spec.coordinates.size());
  for (size_t c = 0; c < all.size(); ++c) all[c] = static_cast<int>(c);
  int locked = 0, coupled = 0;
  for (const std::vector<double>& q : MakePoses(m, 3)) {
    std::vector<std::vector<double>> at_once;
    CalcCouplingVectors(m.spec, m.couplers, q, all, at_once);
    ASSERT_EQ(at_once.size(), all.size());
    for (size_t k = 0; k < all.size(); ++k) {
      const std::vector<double> alone = CalcCouplingVector(m.spec, m.couplers, q, all[k]);
      locked += m.spec.coordinates[k].locked ? 1 : 0;
      int moving = 0;
      for (size_t c = 0; c < alone.size(); ++c) {
        // The same matrix factorized twice: rounding of entries of order 1 (1e-15), with room
        // for the conditioning of A A^T.
        EXPECT_NEAR(at_once[k][c], alone[c], 1e-12) << k << " " << c;
        moving += alone[c] != 0.0 ? 1 : 0;
      }
      coupled += moving > 1 ? 1 : 0;
    }
  }
  EXPECT_GT(locked, 0);   // the locked branch ran
  EXPECT_GT(coupled, 0);  // and some coordinate moves others (the knees their patellae)
}

// With moment arms, PathAnalysis takes each GeometryPath's lengthening speed as dL/du . u from
// the speed columns; without, as the sum over its segments of e . (v_(i+1) - v_i) from the
// body velocities. The two are the same sum in another order: equal to rounding (a few dozen
// additions with partial sums below 1 m/s, 1e-16 each), at poses with wraps, moving points and
// the patellae's couplers. The lengths are the same computation.
TEST(PathDerivativesTest, SpeedsFromTheLengthGradientEqualTheSegmentSums) {
  for (const std::string& file :
       {kDataDir + "/opensim-org/opensim-models/Models/Rajagopal/Rajagopal2016.osim",
        kDataDir + "/MyoHub/myoconverter/models/osim/Leg6Dof9Musc/leg6dof9musc.osim"}) {
    const PathModel m(file);
    std::vector<int> free;
    for (size_t c = 0; c < m.spec.coordinates.size(); ++c) {
      if (!m.spec.coordinates[c].locked && !m.couplers.Drives(static_cast<int>(c))) {
        free.push_back(static_cast<int>(c));
      }
    }
    ASSERT_FALSE(free.empty());
    PathAnalysis with_arms(m.spec, m.tree, m.couplers, m.paths, free);
    PathAnalysis without(m.spec, m.tree, m.couplers, m.paths, {});
    std::mt19937 random(7);
    int moving = 0;
    std::uniform_real_distribution<double> speed(-1.0, 1.0);
    for (const std::vector<double>& q : MakePoses(m, 4)) {
      std::vector<double> u(q.size());
      for (double& u_c : u) u_c = speed(random);
      m.couplers.ApplySpeeds(q, u);
      with_arms.Calc(q, u);
      without.Calc(q, u);
      for (size_t p = 0; p < m.paths.paths().size(); ++p) {
        EXPECT_EQ(with_arms.lengths()[p], without.lengths()[p]);
        EXPECT_NEAR(with_arms.lengthening_speeds()[p], without.lengthening_speeds()[p], 1e-14)
            << file << " " << m.paths.paths()[p].name();
        moving += std::abs(without.lengthening_speeds()[p]) > 1e-3 ? 1 : 0;
      }
    }
    EXPECT_GT(moving, 4 * static_cast<int>(m.paths.paths().size()));  // most paths move
  }
}

// arm26 with its real surfaces: cylinders (one refined, with three wrap objects on TRIlong) and
// ellipsoids. The analytic values are the derivatives of the path with its tangent points
// carried by the bone (asserted inside); against the length wrapped afresh they differ by the
// constructions' kinks (neither OpenSim's cylinder off its cross-sections nor its ellipsoid is
// a shortest path), measured here, bounded at twice that.
TEST(PathDerivativesTest, Arm26MomentArmsOverItsCylindersAndEllipsoids) {
  const double worst =
      CheckMomentArmsAndSpeeds(kDataDir + "/MyoHub/myoconverter/models/osim/Arm26/arm26.osim", 12);
  EXPECT_LT(worst, kArm26Kink);
}

// The envelope argument on a real path: arm26's elbow muscles wrapped over a sphere in place of
// the elbow cylinder (same frame and radius; other wraps disconnected). A sphere's wrap is the
// shortest path over it, so sliding the tangent points along it does not change the length to
// first order: the analytic moment arms and speeds (tangent points carried by the humerus)
// equal the derivatives of the length wrapped afresh at every step, to the differences' bound.
TEST(PathDerivativesTest, OverAShortestPathWrapMomentArmsAreMinusDerivativesOfLength) {
  PathModel m(kDataDir + "/MyoHub/myoconverter/models/osim/Arm26/arm26.osim");
  int spheres = 0;
  for (GeometryPath& path : m.paths.mutable_paths()) {
    for (size_t w = 0; w < path.wraps().size(); ++w) {
      const bool elbow = path.wraps()[w].wrap_object == "TRI";
      const auto* cylinder = dynamic_cast<const WrapCylinder*>(path.wraps()[w].surface.get());
      path.ConnectWrapSurface(
          static_cast<int>(w),
          elbow ? std::make_shared<WrapSphere>(cylinder->radius(), WrapQuadrant{}) : nullptr);
      spheres += elbow ? 1 : 0;
    }
  }
  ASSERT_EQ(spheres, 4);
  // Elbow flexions (with the random shoulder poses) at which the sphere wraps some paths.
  size_t elbow = 0;
  while (elbow < m.spec.coordinates.size() && m.spec.coordinates[elbow].name != "r_elbow_flex") {
    ++elbow;
  }
  ASSERT_LT(elbow, m.spec.coordinates.size());
  std::vector<std::vector<double>> poses;
  int wrapped = 0;
  for (std::vector<double> q : MakePoses(m, 3)) {
    for (double flexion : {0.0, 0.3, 0.7, 1.2, 1.8, 2.2}) {
      q[elbow] = flexion;
      poses.push_back(q);
      for (size_t p = 0; p < m.paths.paths().size(); ++p) {
        wrapped += PathModel::IsWrapped(m.CalcState(static_cast<int>(p), q)) ? 1 : 0;
      }
    }
  }
  EXPECT_GT(wrapped, 10);
  CheckMomentArmsAndSpeeds(m, "arm26 over a sphere", poses, true);
}

int CheckGeneralizedForces(const std::string& file, int num_poses) {
  const PathModel m(file);
  return testing::CheckGeneralizedForces(m, MakePoses(m, num_poses));
}

// test_wrapAllVis's knee-extensor path over its torus (activated; the only active wrap object)
// at the knee angles of its range where it wraps: moment arms and speeds against central
// differences of the length with the tangent points carried by the femur (asserted inside).
// OpenSim's torus path is the shortest only in a meridian plane, which this path is not in, so the
// difference from the length wrapped afresh is only reported.
TEST(PathDerivativesTest, OverATorusMomentArmsAreDerivativesWithTheTangentPointsCarried) {
  const PathModel m(testing::WriteWrapAllVisWithActiveTorus());
  const int knee = m.spec.FindCoordinate("knee_angle_r");
  ASSERT_GE(knee, 0);
  std::vector<std::vector<double>> poses;
  int wrapped = 0;
  for (double angle = -2.0; angle <= 0.1; angle += 0.05) {
    std::vector<double> q = m.tree.default_q();
    q[static_cast<size_t>(knee)] = angle;
    m.couplers.Apply(q);
    // Only poses where the torus wraps: near the others its length jumps (the ring point
    // switching, docs/wrapping.md), and a difference across a jump is no derivative.
    if (!PathModel::IsWrapped(m.CalcState(0, q))) continue;
    ++wrapped;
    poses.push_back(q);
  }
  EXPECT_GT(wrapped, 30);
  CheckMomentArmsAndSpeeds(m, "test_wrapAllVis over its torus", poses, false);
}

TEST(PathDerivativesTest, GeneralizedForceOfATensionIsMinusTensionTimesLengthGradient) {
  CheckGeneralizedForces(
      kDataDir + "/opensim-org/opensim-core/OpenSim/Moco/Test/walk_gait1018_subject01.osim", 4);
}

TEST(PathDerivativesTest, GeneralizedForceOfAWrappedPathIsMinusTensionTimesLengthGradient) {
  EXPECT_GT(CheckGeneralizedForces(
                kDataDir + "/opensim-org/opensim-models/Models/Rajagopal/Rajagopal2016.osim", 2),
            10);
}

}  // namespace
}  // namespace sinew::paths

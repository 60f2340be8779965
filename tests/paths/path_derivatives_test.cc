// The analytic derivatives of path length against central differences of the length itself,
// on models with conditional and moving path points and a coupler: moment arms (with coupled
// coordinates moving together), lengthening speeds, and the generalized force of a tension.
#include <gtest/gtest.h>
#include <sinew/paths/coupling_vector.h>
#include <sinew/paths/path_analysis.h>
#include <sinew/paths/path_loads.h>

#include <cmath>
#include <random>

#include "paths/path_test_util.h"

namespace sinew::paths {
namespace {

using testing::kDataDir;
using testing::PathModel;

// Central differences with step h and h/2: their Richardson combination (4 D(h/2) - D(h)) / 3,
// and |D(h/2) - D(h)|, which bounds its truncation error (three times D(h/2)'s). Knees whose
// splines have closely spaced knots make L''' large at some poses (walk_gait1018's vasti
// at knee angle 0: D(1e-5) is off by 2e-7 m), so the bound is estimated, not assumed. Rounding
// adds eps L / h ~ 1e-12 m; kRounding allows a thousand times that.
constexpr double kStep = 1e-4;
constexpr double kRounding = 1e-9;

struct Difference {
  double value;  // the Richardson estimate of the derivative
  double error;  // the bound on its truncation error
};

// d/dh f(h) at h = 0 from f(+-kStep) and f(+-kStep/2).
template <typename F>
Difference Differentiate(const F& f) {
  const double d1 = (f(kStep) - f(-kStep)) / (2 * kStep);
  const double d2 = (f(kStep / 2) - f(-kStep / 2)) / kStep;
  return {(4 * d2 - d1) / 3, std::abs(d2 - d1)};
}

// Poses to check: the defaults and random poses within the coordinates' ranges (10% in from
// each end), drawn with a fixed seed. A pose where a conditional point is within 10 steps of
// its range limit, or a moving point's coordinate is out of range, is skipped: L is not
// differentiable there.
std::vector<std::vector<double>> MakePoses(const PathModel& m, int count) {
  std::mt19937 random(1234);
  std::vector<std::vector<double>> poses{m.tree.default_q()};
  for (int k = 0; k < count; ++k) {
    std::vector<double> q = m.tree.default_q();
    for (size_t c = 0; c < q.size(); ++c) {
      const model::CoordinateSpec& s = m.spec.coordinates[c];
      const double lo = std::max(s.range_min, -3.0), hi = std::min(s.range_max, 3.0);
      std::uniform_real_distribution<double> in_range(lo + 0.1 * (hi - lo), hi - 0.1 * (hi - lo));
      q[c] = in_range(random);
    }
    m.couplers.Apply(q);
    poses.push_back(q);
  }
  return poses;
}

// A conditional point switches within two steps of q: L is not differentiable there.
bool NearAConditionalLimit(const PathModel& m, const std::vector<double>& q) {
  for (const GeometryPath& path : m.paths.paths()) {
    for (const PathPoint& point : path.points()) {
      if (point.kind != PathPointKind::kConditional) continue;
      const double value = q[point.coordinate];
      for (double limit : {point.range_min - kConditionalRangeTolerance,
                           point.range_max + kConditionalRangeTolerance}) {
        if (std::abs(value - limit) < 2 * kStep) return true;
      }
    }
  }
  return false;
}

// q moved by h along the coupling vector c (couplers reapplied so the pose stays consistent).
std::vector<double> Move(const PathModel& m, std::vector<double> q, const std::vector<double>& c,
                         double h) {
  for (size_t k = 0; k < q.size(); ++k) q[k] += h * c[k];
  m.couplers.Apply(q);
  return q;
}

void CheckMomentArmsAndSpeeds(const std::string& file, int num_poses) {
  const PathModel m(file);
  ASSERT_FALSE(m.paths.paths().empty());
  std::vector<int> all(m.spec.coordinates.size());
  for (size_t c = 0; c < all.size(); ++c) all[c] = static_cast<int>(c);
  PathAnalysis analysis(m.spec, m.tree, m.couplers, m.paths, all);
  std::mt19937 random(99);
  std::uniform_real_distribution<double> speed(-2.0, 2.0);
  int checked = 0;
  for (const std::vector<double>& q : MakePoses(m, num_poses)) {
    if (NearAConditionalLimit(m, q)) continue;
    std::vector<double> u(q.size());
    for (double& x : u) x = speed(random);
    m.couplers.ApplySpeeds(q, u);
    analysis.Calc(q, u);
    for (size_t p = 0; p < m.paths.paths().size(); ++p) {
      const int path = static_cast<int>(p);
      // Lengthening speed: d/dt L(q + t u) at t = 0.
      const Difference Ldot =
          Differentiate([&](double h) { return m.CalcLength(path, Move(m, q, u, h)); });
      EXPECT_NEAR(analysis.lengthening_speeds()[p], Ldot.value, Ldot.error + kRounding)
          << m.paths.paths()[p].name();
      for (size_t k = 0; k < all.size(); ++k) {
        const std::vector<double> c = CalcCouplingVector(m.spec, m.couplers, q, all[k]);
        const Difference dL =
            Differentiate([&](double h) { return m.CalcLength(path, Move(m, q, c, h)); });
        EXPECT_NEAR(analysis.moment_arm(k, p), -dL.value, dL.error + kRounding)
            << m.paths.paths()[p].name() << " about " << m.spec.coordinates[all[k]].name;
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 0);
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
// the patella along; the moving-point-free paths test the coupling vector alone.
TEST(PathDerivativesTest, Rajagopal2016MomentArmsFollowTheCoupledPatellae) {
  CheckMomentArmsAndSpeeds(
      kDataDir + "/opensim-org/opensim-models/Models/Rajagopal/Rajagopal2016.osim", 2);
}

// The generalized force of a tension T is -T dL/du (power balance), checked against central
// differences of L about each coordinate alone (no coupling).
TEST(PathDerivativesTest, GeneralizedForceOfATensionIsMinusTensionTimesLengthGradient) {
  const PathModel m(kDataDir +
                    "/opensim-org/opensim-core/OpenSim/Moco/Test/walk_gait1018_subject01.osim");
  const double tension = 250.0;
  for (const std::vector<double>& q : MakePoses(m, 4)) {
    if (NearAConditionalLimit(m, q)) continue;
    std::vector<Transform> X_GB(static_cast<size_t>(m.tree.num_bodies()));
    kinematics::CalcBodyPoses(m.tree, q, X_GB);
    SpeedColumns columns;
    CalcSpeedColumns(m.tree, q, X_GB, columns);
    for (size_t p = 0; p < m.paths.paths().size(); ++p) {
      const int path = static_cast<int>(p);
      PathState state;
      m.paths.paths()[p].CalcState(q, X_GB, state);
      PathLoads loads;
      CalcPathLoads(state, X_GB, tension, loads);
      std::vector<double> Q(q.size(), 0.0);
      AddGeneralizedForces(loads, X_GB, columns, Q);
      for (size_t k = 0; k < q.size(); ++k) {
        const Difference dL = Differentiate([&](double h) {
          std::vector<double> moved = q;
          moved[k] += h;
          return m.CalcLength(path, moved);
        });
        EXPECT_NEAR(Q[k], -tension * dL.value, tension * (dL.error + kRounding))
            << m.paths.paths()[p].name() << " on " << m.spec.coordinates[k].name;
      }
    }
  }
}

}  // namespace
}  // namespace sinew::paths

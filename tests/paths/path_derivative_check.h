// Moment arms and lengthening speeds against central differences of path length, shared by
// the path derivative tests and the corpus sweep.
#pragma once

#include <gtest/gtest.h>
#include <sinew/paths/coupling_vector.h>
#include <sinew/paths/path_analysis.h>
#include <sinew/paths/path_loads.h>
#include <sinew/paths/speed_columns.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "paths/path_test_util.h"

namespace sinew::paths::testing {

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
inline std::vector<std::vector<double>> MakePoses(const PathModel& m, int count) {
  std::mt19937 random(1234);
  std::vector<double> defaults = m.tree.default_q();
  m.couplers.Apply(defaults);  // a file's defaults need not satisfy its couplers (leg39's knee)
  std::vector<std::vector<double>> poses{defaults};
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
inline bool NearAConditionalLimit(const PathModel& m, const std::vector<double>& q) {
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

// q moved by h along the coupling vector c (couplers reapplied so the pose stays consistent,
// unless `couple` is false).
inline std::vector<double> Move(const PathModel& m, std::vector<double> q,
                                const std::vector<double>& c, double h, bool couple = true) {
  for (size_t k = 0; k < q.size(); ++k) q[k] += h * c[k];
  if (couple) m.couplers.Apply(q);
  return q;
}

// qdot = N(q) u, joint by joint: speeds u are not the coordinates' rates for BallJoint,
// FreeJoint's rotation and EllipsoidJoint (an angular velocity; joint_model.h), so a direction
// of speeds moves q along N(q) u.
inline std::vector<double> CalcQDot(const PathModel& m, const std::vector<double>& q,
                                    const std::vector<double>& u) {
  std::vector<double> qdot = u;
  for (const kinematics::TreeJoint& joint : m.tree.joints()) {
    std::array<double, 6> q_joint{}, u_joint{}, qdot_joint{};
    for (int i = 0; i < joint.nq; ++i) {
      q_joint[i] = q[joint.q_index[i]];
      u_joint[i] = u[joint.q_index[i]];
    }
    const auto n = static_cast<size_t>(joint.nq);
    joint.model->CalcQDot(std::span(q_joint).first(n), std::span(u_joint).first(n),
                          std::span(qdot_joint).first(n));
    for (int i = 0; i < joint.nq; ++i) qdot[joint.q_index[i]] = qdot_joint[i];
  }
  return qdot;
}

// The derivative of f(q) along the speeds `direction` at q: d/dh f(q + h N(q) direction). The
// step is scaled so that no coordinate moves more than kStep (a coupling vector may be large:
// a coordinate that barely moves its coupled partners), and the bound scaled back.
template <typename F>
Difference DifferentiateAlong(const PathModel& m, const std::vector<double>& q,
                              const std::vector<double>& direction, const F& f,
                              bool couple = true) {
  std::vector<double> qdot = CalcQDot(m, q, direction);
  double scale = 0.0;
  for (double x : qdot) scale = std::max(scale, std::abs(x));
  if (scale == 0.0) return {0.0, 0.0};
  for (double& x : qdot) x /= scale;
  const Difference d = Differentiate([&](double h) { return f(Move(m, q, qdot, h, couple)); });
  return {scale * d.value, scale * (d.error + kRounding)};
}

// Moment arms and lengthening speeds of every path at every pose against central differences of
// the length with the wraps' tangent points fixed on their bodies (what the analytic values
// are the derivatives of; docs/paths.md), to the differences' own bound. Against the length
// wrapped afresh at each step they agree as tightly on every path that does not wrap at q;
// on wrapped paths the two differ by the first-order length change of moving the tangent
// points along the surface, zero for an exact shortest path (the sphere, the cylinder with P
// and S at one height) and not for OpenSim's other constructions (docs/wrapping.md). Returns
// the largest such difference on wrapped paths, for the caller to bound.
// With `shortest`, the wrapped paths are exact shortest paths and are held to the bound too.
inline double CheckMomentArmsAndSpeeds(const PathModel& m, const std::string& name,
                                       const std::vector<std::vector<double>>& poses,
                                       bool shortest) {
  EXPECT_FALSE(m.paths.paths().empty());
  std::vector<int> all(m.spec.coordinates.size());
  for (size_t c = 0; c < all.size(); ++c) all[c] = static_cast<int>(c);
  PathAnalysis analysis(m.spec, m.tree, m.couplers, m.paths, all);
  std::mt19937 random(99);
  std::uniform_real_distribution<double> speed(-2.0, 2.0);
  int checked = 0, checked_wrapped = 0, checked_stale = 0, immobile = 0;
  double worst_rewrapped = 0.0, worst_stale = 0.0;
  for (const std::vector<double>& q : poses) {
    if (NearAConditionalLimit(m, q)) continue;
    std::vector<double> u(q.size());
    for (double& x : u) x = speed(random);
    m.couplers.ApplySpeeds(q, u);
    analysis.Calc(q, u);
    for (size_t p = 0; p < m.paths.paths().size(); ++p) {
      const int path = static_cast<int>(p);
      const PathState at = m.CalcState(path, q);
      const bool wrapped = PathModel::IsWrapped(at);
      const bool stale = at.stale_tangent_points > 0;
      checked_wrapped += wrapped && !stale ? 1 : 0;
      checked_stale += stale ? 1 : 0;
      // The length through the tangent points of q, and the length wrapped afresh.
      const auto fixed = [&](const std::vector<double>& moved) {
        return m.CalcLengthThrough(path, moved, at);
      };
      const auto rewrapped = [&](const std::vector<double>& moved) {
        return m.CalcLength(path, moved);
      };
      const auto check = [&](double analytic, const std::vector<double>& direction,
                             const std::string& what) {
        const Difference d = DifferentiateAlong(m, q, direction, fixed);
        EXPECT_NEAR(analytic, d.value, d.error) << what;
        const Difference r = DifferentiateAlong(m, q, direction, rewrapped);
        if (stale) {
          worst_stale = std::max(worst_stale, std::abs(analytic - r.value));
        } else if (wrapped && !shortest) {
          worst_rewrapped = std::max(worst_rewrapped, std::abs(analytic - r.value));
        } else {
          EXPECT_NEAR(analytic, r.value, r.error) << what << " (wrapped afresh)";
        }
      };
      // Lengthening speed: d/dt L(q + t u) at t = 0.
      check(analysis.lengthening_speeds()[p], u, m.paths.paths()[p].name() + " speed");
      for (size_t k = 0; k < all.size(); ++k) {
        const std::vector<double> c = CalcCouplingVector(m.spec, m.couplers, q, all[k]);
        if (std::isnan(c[0])) {
          // The constraints leave the coordinate no motion (a coupler with a flat function
          // drives it): its moment arm is undefined, NaN as OpenSim's division by zero gives.
          EXPECT_TRUE(std::isnan(analysis.moment_arm(k, p)));
          ++immobile;
          continue;
        }
        // The moment arm is -dL/dq.
        check(-analysis.moment_arm(k, p), c,
              m.paths.paths()[p].name() + " about " + m.spec.coordinates[all[k]].name);
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 0);
  std::cout << name << ": " << checked << " moment arms checked (" << immobile
            << " about coordinates the constraints hold still, NaN), " << checked_wrapped
            << " wrapped path states; worst |analytic - d/dq of the length "
            << "wrapped afresh| on wrapped paths " << worst_rewrapped << " m; " << checked_stale
            << " path states with stale tangent points, worst " << worst_stale << " m\n";
  return worst_rewrapped;
}

// The generalized force of a tension T is -T dL/du (power balance), checked against central
// differences of L along each speed alone (no coupling), the tangent points of wrapped
// paths carried by their bodies. Returns the number of wrapped path states checked.
inline int CheckGeneralizedForces(const PathModel& m,
                                  const std::vector<std::vector<double>>& poses) {
  const double tension = 250.0;
  int wrapped = 0;
  for (const std::vector<double>& q : poses) {
    if (NearAConditionalLimit(m, q)) continue;
    std::vector<Transform> X_GB(static_cast<size_t>(m.tree.num_bodies()));
    kinematics::CalcBodyPoses(m.tree, q, X_GB);
    SpeedColumns columns;
    CalcSpeedColumns(m.tree, q, X_GB, columns);
    for (size_t p = 0; p < m.paths.paths().size(); ++p) {
      const int path = static_cast<int>(p);
      PathState state;
      m.paths.paths()[p].CalcState(q, X_GB, state);
      wrapped += PathModel::IsWrapped(state) ? 1 : 0;
      PathLoads loads;
      CalcPathLoads(state, X_GB, tension, loads);
      std::vector<double> Q(q.size(), 0.0);
      AddGeneralizedForces(loads, X_GB, columns, Q);
      for (size_t k = 0; k < q.size(); ++k) {
        std::vector<double> e_k(q.size(), 0.0);
        e_k[k] = 1.0;
        const Difference dL = DifferentiateAlong(
            m, q, e_k,
            [&](const std::vector<double>& moved) {
              return m.CalcLengthThrough(path, moved, state);
            },
            false);
        EXPECT_NEAR(Q[k], -tension * dL.value, tension * dL.error)
            << m.paths.paths()[p].name() << " on " << m.spec.coordinates[k].name;
      }
    }
  }
  return wrapped;
}

}  // namespace sinew::paths::testing

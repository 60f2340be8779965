#include <sinew/common/error.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/assemble_state.h>
#include <sinew/engine/kkt.h>
#include <sinew/engine/projection.h>

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace sinew::engine {
namespace {

constexpr int kMaxIterations = 100;
// Gauss-Newton leaves out the constraints' curvature, so near the solution the goal's steps
// converge only linearly and leave errors of their square in phi; after this many iterations
// the goal is dropped and Newton steps of minimum weighted norm finish the constraints.
constexpr int kGoalIterations = 60;
// Relative step of the central differences of phi(q): balances the O(h^2) truncation against
// rounding (eps / h) near the cube root of machine epsilon.
constexpr double kDifferenceStep = 5e-6;
// Damping of the steps of coordinates the goal does not weigh (weight 0): it only shapes the
// steps, not the solution (at the solution the step is zero).
constexpr double kStepDamping = 1e-8;
// A converged step: this much (rad or m) relative to max(1, |q|).
constexpr double kStepTolerance = 1e-11;

// The constraints the tree placement of bodies does not satisfy by itself: loop joints and the
// extra constraints (couplers, welds, ...). Their rows make up the residual.
struct Residual {
  std::vector<int> constraints;  ///< indices into System::constraints()
  std::vector<int> first_row;    ///< first residual row of each
  int rows = 0;

  explicit Residual(const System& system) {
    for (int j = 0; j < static_cast<int>(system.joints().size()); ++j) {
      if (system.IsLoop(j)) constraints.push_back(j);
    }
    const int all = static_cast<int>(system.constraints().size());
    for (int k = system.FirstExtraConstraint(); k < all; ++k) constraints.push_back(k);
    for (int k : constraints) {
      first_row.push_back(rows);
      rows += system.constraints()[k]->NumEquations();
    }
  }

  // phi of those constraints with the bodies placed from state.q.
  VecX Calc(const System& system, State& state) const {
    PlaceBodies(system, state);
    VecX phi(rows);
    for (size_t i = 0; i < constraints.size(); ++i) {
      const Constraint& c = *system.constraints()[constraints[i]];
      c.CalcPositionError(system, state, phi.segment(first_row[i], c.NumEquations()));
    }
    return phi;
  }

  // "'name' (residual), ..." for the (up to three) constraints with the largest |phi|.
  std::string Worst(const System& system, const VecX& phi) const {
    std::vector<std::pair<double, int>> largest;
    for (size_t i = 0; i < constraints.size(); ++i) {
      const int n = system.constraints()[constraints[i]]->NumEquations();
      const auto own = phi.segment(first_row[i], n);
      const double worst =
          own.allFinite() ? own.lpNorm<Eigen::Infinity>() : std::numeric_limits<double>::infinity();
      largest.emplace_back(worst, constraints[i]);
    }
    std::sort(largest.begin(), largest.end(), std::greater<>());
    std::string out;
    for (size_t i = 0; i < largest.size() && i < 3 && largest[i].first > 0.0; ++i) {
      std::string name = system.constraints()[largest[i].second]->name();
      if (name.empty()) name = "constraint " + std::to_string(largest[i].second);
      char value[32];
      std::snprintf(value, sizeof(value), "%.3g", largest[i].first);
      out += (out.empty() ? "'" : ", '") + name + "' (" + value + ")";
    }
    return out;
  }
};

// A = dphi/dq over the free coordinates, by central differences of the tree placement.
MatX CalcResidualJacobian(const System& system, const Residual& residual,
                          const std::vector<int>& free, State& state) {
  MatX A(residual.rows, static_cast<Eigen::Index>(free.size()));
  for (size_t i = 0; i < free.size(); ++i) {
    double& q = state.q[free[i]];
    const double q0 = q;
    const double h = kDifferenceStep * std::max(1.0, std::abs(q0));
    q = q0 + h;
    const VecX plus = residual.Calc(system, state);
    q = q0 - h;
    const VecX minus = residual.Calc(system, state);
    q = q0;
    A.col(static_cast<Eigen::Index>(i)) = (plus - minus) / (2 * h);
  }
  return A;
}

}  // namespace

void AssembleState(const System& system, State& state, double tolerance) {
  CheckState(system, state);
  const Residual residual(system);
  std::vector<int> free;
  for (int c = 0; c < system.num_coordinates(); ++c) {
    if (system.coordinates()[c].motion == CoordinateMotion::kFree) free.push_back(c);
  }
  const int n = static_cast<int>(free.size());
  VecX goal(n), weight(n);
  for (int i = 0; i < n; ++i) {
    goal[i] = state.q[free[i]];
    weight[i] = system.coordinates()[free[i]].assembly_weight;
  }
  const double largest_weight = n > 0 ? weight.maxCoeff() : 0.0;
  const VecX step_weight = weight.array() + kStepDamping * std::max(1.0, largest_weight);

  VecX phi = residual.Calc(system, state);
  double error = phi.size() == 0 ? 0.0 : phi.lpNorm<Eigen::Infinity>();
  if (!phi.allFinite()) error = std::numeric_limits<double>::infinity();
  for (int iteration = 0; iteration < kMaxIterations && phi.size() > 0 && n > 0; ++iteration) {
    // Linearized problem: min sum_i w_i (q_i + dq_i - goal_i)^2 subject to phi + A dq = 0.
    // With H = diag(w + damping) and g = w (q - goal): dq = -H^-1 (g + A^T lambda) where
    // (A H^-1 A^T) lambda = phi - A H^-1 g; a complete orthogonal decomposition gives redundant
    // constraints (a four-bar's loop) minimum-norm multipliers.
    VecX q(n);
    for (int i = 0; i < n; ++i) q[i] = state.q[free[i]];
    const MatX A = CalcResidualJacobian(system, residual, free, state);
    const bool with_goal = iteration < kGoalIterations;
    const VecX g = with_goal ? VecX(weight.cwiseProduct(q - goal)) : VecX(VecX::Zero(n));
    const MatX AHinv = A * step_weight.cwiseInverse().asDiagonal();
    const MatX S = AHinv * A.transpose();
    const VecX lambda = S.completeOrthogonalDecomposition().solve(phi - AHinv * g);
    const VecX dq = -step_weight.cwiseInverse().cwiseProduct(g + A.transpose() * lambda);
    if (!dq.allFinite()) break;
    // Halve the step while it makes the constraint error worse (far from the solution).
    double alpha = 1.0;
    VecX trial_phi;
    bool accepted = false;
    for (int halving = 0; halving < 20 && !accepted; ++halving) {
      if (halving > 0) alpha *= 0.5;
      for (int i = 0; i < n; ++i) state.q[free[i]] = q[i] + alpha * dq[i];
      trial_phi = residual.Calc(system, state);
      accepted = trial_phi.allFinite() &&
                 trial_phi.lpNorm<Eigen::Infinity>() <= std::max(error, tolerance);
    }
    if (!accepted) {  // no step along dq reduces the error: stalled, keep the last state
      for (int i = 0; i < n; ++i) state.q[free[i]] = q[i];
      phi = residual.Calc(system, state);
      break;
    }
    phi = trial_phi;
    error = phi.lpNorm<Eigen::Infinity>();
    const double scale = std::max(1.0, q.lpNorm<Eigen::Infinity>());
    if (error <= tolerance &&
        (!with_goal || alpha * dq.lpNorm<Eigen::Infinity>() <= kStepTolerance * scale)) {
      break;
    }
  }
  if (error > tolerance) {
    throw Error(
        "engine: cannot assemble a state that satisfies the constraints; largest "
        "residuals: " +
        residual.Worst(system, phi));
  }
  PlaceBodies(system, state);
  KktSolver kkt(system);
  ProjectVelocities(system, state, kkt);
  UpdateDirectCoordinates(system, state);
}

}  // namespace sinew::engine

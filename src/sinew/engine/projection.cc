#include <sinew/common/error.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/pose.h>
#include <sinew/engine/projection.h>

#include <cmath>
#include <limits>
#include <vector>

namespace sinew::engine {

VecX CalcPositionErrors(const System& system, const State& state) {
  int n = 0;
  for (const auto& c : system.constraints()) n += c->NumEquations();
  VecX phi(n);
  int row = 0;
  for (const auto& c : system.constraints()) {
    c->CalcPositionError(system, state, phi.segment(row, c->NumEquations()));
    row += c->NumEquations();
  }
  return phi;
}

VecX CalcVelocityErrors(const System& system, const State& state, KktSolver& kkt) {
  kkt.Factorize(state);
  VecX err = kkt.MultiplyJacobian(GatherVelocities(system, kkt, state));
  const auto& constraints = system.constraints();
  for (size_t k = 0; k < constraints.size(); ++k) {
    VecX c(constraints[k]->NumEquations());
    constraints[k]->CalcVelocityRhs(system, state, c);
    err.segment(kkt.EquationRow(k), c.size()) -= c;
  }
  return err;
}

void ApplyPositionDisplacement(const System& system, const KktSolver& kkt, const VecX& dx,
                               State& state) {
  for (int b = 1; b < system.num_bodies(); ++b) {
    BodyState& s = state.bodies[b];
    s.quat_GB = (QuatFromRotationVector(dx.segment<3>(kkt.BodyColumn(b))) * s.quat_GB).normalized();
    s.p_GB += dx.segment<3>(kkt.BodyColumn(b) + 3);
  }
  for (const Joint& joint : system.joints()) {
    if (joint.form != JointForm::kParameterized || joint.coordinates.empty()) continue;
    const size_t n = joint.coordinates.size();
    std::vector<double> q(n), du(n), dq(n);
    for (size_t i = 0; i < n; ++i) {
      q[i] = state.q[joint.coordinates[i]];
      du[i] = dx[kkt.SpeedColumn(joint.coordinates[i])];
    }
    joint.model->CalcQDot(q, du, dq);
    for (size_t i = 0; i < n; ++i) state.q[joint.coordinates[i]] += dq[i];
  }
}

bool ProjectPositions(const System& system, State& state, double tolerance, KktSolver& kkt,
                      int max_iterations, long* factorizations) {
  const int nv = kkt.num_velocities();
  double previous = std::numeric_limits<double>::infinity();
  for (int iteration = 0; iteration <= max_iterations; ++iteration) {
    const VecX phi = CalcPositionErrors(system, state);
    const double error = phi.size() == 0 ? 0.0 : phi.lpNorm<Eigen::Infinity>();
    if (error <= tolerance) return true;
    if (iteration == max_iterations) break;
    // Modified Newton: keep the matrix while the error falls fast (it does for the small
    // corrections after an integration step); refactorize otherwise. With a kept matrix the
    // error only falls linearly, by about error / previous per iteration, so the matrix is also
    // refactorized when that rate would not reach the tolerance in the iterations left (a large
    // correction, e.g. after a long fixed step, can settle at a rate just under 0.1 and stall).
    const double rate = error / previous;
    const int left = max_iterations - iteration;
    if (iteration == 0 || rate > 0.1 || error * std::pow(rate, left) > tolerance) {
      kkt.Factorize(state);
      if (factorizations) ++*factorizations;
    }
    previous = error;
    VecX rhs = VecX::Zero(nv + phi.size());
    rhs.tail(phi.size()) = -phi;
    ApplyPositionDisplacement(system, kkt, kkt.Solve(rhs).head(nv), state);
  }
  return false;
}

void ProjectVelocities(const System& system, State& state, KktSolver& kkt) {
  const int nv = kkt.num_velocities();
  kkt.Factorize(state);
  const VecX v0 = GatherVelocities(system, kkt, state);
  VecX rhs(nv + kkt.num_equations());
  rhs.head(nv) = kkt.MultiplyMass(v0);
  const auto& constraints = system.constraints();
  for (size_t k = 0; k < constraints.size(); ++k) {
    constraints[k]->CalcVelocityRhs(
        system, state, rhs.segment(nv + kkt.EquationRow(k), constraints[k]->NumEquations()));
  }
  ScatterVelocities(system, kkt, kkt.Solve(rhs).head(nv), state);
}

void ProjectState(const System& system, State& state, double tolerance) {
  CheckState(system, state);
  KktSolver kkt(system);
  if (!ProjectPositions(system, state, tolerance, kkt, 50)) {
    throw Error("engine: cannot satisfy the constraints from this state");
  }
  ProjectVelocities(system, state, kkt);
  UpdateDirectCoordinates(system, state);
}

}  // namespace sinew::engine

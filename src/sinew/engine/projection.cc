#include <sinew/common/error.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/joint_values.h>
#include <sinew/engine/pose.h>
#include <sinew/engine/projection.h>

#include <cmath>
#include <limits>

namespace sinew::engine {
namespace {

// The projections' buffers, one set per thread (a System serves many threads).
struct ProjectionBuffers {
  VecX phi, rhs, solution, v, mv;
};
ProjectionBuffers& Buffers() {
  thread_local ProjectionBuffers buffers;
  return buffers;
}

}  // namespace

VecX CalcPositionErrors(const System& system, const State& state) {
  VecX phi;
  CalcPositionErrors(system, state, phi);
  return phi;
}

void CalcPositionErrors(const System& system, const State& state, VecX& phi, ErrorRows rows) {
  const auto& constraints = system.constraints();
  int n = 0;
  for (const auto& c : constraints) n += c->NumEquations();
  phi.resize(n);
  int row = 0;
  for (size_t k = 0; k < constraints.size(); ++k) {
    const int m = constraints[k]->NumEquations();
    if (rows == ErrorRows::kNotHeldByTree && system.HeldByTreePlacement(static_cast<int>(k))) {
      phi.segment(row, m).setZero();
    } else {
      constraints[k]->CalcPositionError(system, state, phi.segment(row, m));
    }
    row += m;
  }
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
  AdvanceIntegratedCoordinates(system, kkt, dx, state);
}

void AdvanceIntegratedCoordinates(const System& system, const KktSolver& kkt, const VecX& dx,
                                  State& state) {
  for (const Joint& joint : system.joints()) {
    if (joint.form != JointForm::kParameterized || joint.coordinates.empty()) continue;
    const JointValues q(state.q, joint.coordinates);
    JointValues du(q.size()), dq(q.size());
    for (size_t i = 0; i < q.size(); ++i) du[i] = dx[kkt.SpeedColumn(joint.coordinates[i])];
    joint.model->CalcQDot(q, du, dq);
    for (size_t i = 0; i < q.size(); ++i) state.q[joint.coordinates[i]] += dq[i];
  }
}

bool ProjectPositions(const System& system, State& state, double tolerance, KktSolver& kkt,
                      int max_iterations, long* factorizations) {
  const int nv = kkt.num_velocities();
  ProjectionBuffers& buffers = Buffers();
  VecX& phi = buffers.phi;
  double previous = std::numeric_limits<double>::infinity();
  for (int iteration = 0; iteration <= max_iterations; ++iteration) {
    CalcPositionErrors(system, state, phi);
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
    // The first matrix may be one already made at these positions (rk45's last stage was
    // evaluated at the step's end): the same factorization, bit for bit.
    const bool refactorize = iteration == 0
                                 ? !kkt.IsFactorizedAt(state)
                                 : rate > 0.1 || error * std::pow(rate, left) > tolerance;
    if (refactorize) {
      kkt.Factorize(state);
      if (factorizations) ++*factorizations;
    }
    previous = error;
    buffers.rhs.setZero(nv + phi.size());
    buffers.rhs.tail(phi.size()) = -phi;
    kkt.Solve(buffers.rhs, buffers.solution);
    buffers.v = buffers.solution.head(nv);
    ApplyPositionDisplacement(system, kkt, buffers.v, state);
  }
  return false;
}

void ProjectVelocities(const System& system, State& state, KktSolver& kkt) {
  const int nv = kkt.num_velocities();
  if (!kkt.IsFactorizedAt(state)) kkt.Factorize(state);
  ProjectionBuffers& buffers = Buffers();
  buffers.v.resize(nv);
  GatherVelocities(system, kkt, state, buffers.v);
  VecX& rhs = buffers.rhs;
  rhs.resize(nv + kkt.num_equations());
  kkt.MultiplyMass(buffers.v, buffers.mv);
  rhs.head(nv) = buffers.mv;
  const auto& constraints = system.constraints();
  for (size_t k = 0; k < constraints.size(); ++k) {
    constraints[k]->CalcVelocityRhs(
        system, state, rhs.segment(nv + kkt.EquationRow(k), constraints[k]->NumEquations()));
  }
  kkt.Solve(rhs, buffers.solution);
  ScatterVelocities(system, kkt, buffers.solution.head(nv), state);
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

// Stage "accelerations" of one evaluation: loads (gravity, force elements, external loads),
// then the KKT solve for body accelerations, joint-speed derivatives and constraint multipliers.
#pragma once

#include <sinew/common/error.h>
#include <sinew/engine/kkt.h>
#include <sinew/engine/loads.h>
#include <sinew/engine/state.h>
#include <sinew/engine/system.h>

namespace sinew::engine {

/// Result of CalcAccelerations, in KKT velocity order (see KktSolver).
struct Accelerations {
  /// Body spatial accelerations [alpha_GB; a_GBo] (in G) and integrated speed derivatives udot.
  VecX vdot;
  /// Constraint multipliers, one per constraint equation (reaction loads in the rows' units).
  VecX lambda;
};

/// Thrown by an evaluation when a force element's loads or state-variable derivatives are not
/// finite (say, at an integrator's trial state far outside a muscle's curves); component() names
/// the force. Error-controlled integrators take it as a failed step and retry a smaller one.
class NonFiniteForceError : public Error {
 public:
  using Error::Error;
};

/// Turns generalized forces on coordinates of direct Cartesian joints into the body torques they
/// are (along the columns of H_FM, in F: tau on the child, -tau on the parent).
void MapDirectJointForces(const System& system, const State& state, Loads& loads);

/// Adds gravity, every force element of `system` and `external` (may be null) for `state`.
/// Generalized forces on coordinates of direct Cartesian joints are turned into body torques.
/// With `zdot` (System::num_state_variables() entries), also CalcStateVariableDerivatives,
/// visiting each element once (ForceElement::AddLoadsAndStateVariableDerivatives: a muscle's
/// path and fiber dynamics are computed once for both).
void CalcLoads(const System& system, const State& state, const Loads* external, Loads& loads,
               Eigen::Ref<VecX>* zdot = nullptr);

/// dz/dt of every auxiliary state variable at `state` (System::num_state_variables() entries).
/// Throws NonFiniteForceError naming the first force whose derivatives are not finite.
void CalcStateVariableDerivatives(const System& system, const State& state, Eigen::Ref<VecX> zdot);

/// The workspace of one thread's evaluations of a System: what an evaluation computes, kept so
/// that nothing is allocated on the heap per evaluation (`DataTest.EvaluationAllocatesNothing`).
/// Stages: the body poses and twists are the State itself in the Cartesian form; `loads` (the
/// applied loads), then `kkt` (mass matrices, constraint Jacobians and their factors), then
/// `accelerations`. Force elements will find cached geometry here (muscle paths) as it comes.
/// Not shareable between threads: make one per thread (a System is shared).
struct Data {
  explicit Data(const System& system, KktSolver::Method method = KktSolver::Method::kTree);
  KktSolver kkt;                ///< the constrained mass matrix of the last evaluation, factorized
  Loads loads;                  ///< applied loads of the last evaluation
  VecX rhs;                     ///< KKT right-hand side [f - bias; b]
  VecX solution;                ///< KKT solution [vdot; lambda]
  Accelerations accelerations;  ///< the last evaluation's results
};

/// The velocity rows of the KKT right-hand side (KKT velocity order, nv entries) for data.loads
/// at `state`: each body's applied loads minus its velocity-dependent (gyroscopic, centripetal)
/// terms, and each integrated coordinate's generalized force. Throws NonFiniteForceError naming
/// the first source that is not finite.
void CalcForceRhs(const System& system, const State& state, const Loads* external, const Data& data,
                  Eigen::Ref<VecX> rhs);

/// CalcLoads, data.kkt factorized at `state` (kept when it was made at `state`'s positions), then
/// CalcForceRhs: what a velocity-level step needs of an evaluation, M v+ + J^T mu = M v + h f,
/// without the acceleration solve.
void CalcForceRhsReusingFactorization(const System& system, const State& state,
                                      const Loads* external, Data& data, Eigen::Ref<VecX> rhs,
                                      Eigen::Ref<VecX>* zdot = nullptr);

/// The accelerations of `state` under the loads of CalcLoads, into data.accelerations (also
/// returned). `data` must belong to `system`. Throws NonFiniteForceError naming the force when
/// the loads are not finite, and sinew::Error for a singular system.
const Accelerations& CalcAccelerations(const System& system, const State& state,
                                       const Loads* external, Data& data);

/// CalcAccelerations that keeps data.kkt's factorization when it was made at `state`'s
/// positions (KktSolver::IsFactorizedAt): the same result, bit for bit, without refactorizing
/// (a fixed-step integrator's velocity projection factorizes at the next step's start). With
/// `zdot`, also the state variables' derivatives (CalcLoads).
const Accelerations& CalcAccelerationsReusingFactorization(const System& system, const State& state,
                                                           const Loads* external, Data& data,
                                                           Eigen::Ref<VecX>* zdot = nullptr);

}  // namespace sinew::engine

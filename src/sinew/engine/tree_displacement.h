// The fixed-step schemes' position update along the joint tree.
#pragma once

#include <sinew/engine/kkt.h>
#include <sinew/engine/state.h>
#include <sinew/engine/system.h>

namespace sinew::engine {

/// Moves `state` by the displacement `dx` (a step's velocities times the step, laid out as the
/// KKT system's velocity unknowns) along the joint tree, instead of moving each body rigidly by
/// its own twist (ApplyPositionDisplacement):
/// - each tree joint advances by its share of dx, measured at the poses before the step: a
///   parameterized joint's coordinates by N(q) du, a Pin's and a Universal's angles by their
///   rates, a Ball's rotation by the exponential of its relative rotation vector (in F), a Weld
///   not at all;
/// - then every body is placed from its inboard body through its joint, walking out from
///   ground: X_GB = X_GP X_PF X_FM inverse(X_BM).
/// Both updates are first order and differ by O(|dx|^2); this one leaves the tree's joints
/// satisfied to rounding, so the projection after a step only has loop joints and extra
/// constraints (couplers, locks and prescribed motions of coordinates) left to correct.
/// `state` must hold the step's new velocities (it reads each direct joint's relative twist
/// from dx, and its coordinates from state.q).
void ApplyTreeDisplacement(const System& system, const KktSolver& kkt, const VecX& dx,
                           State& state);

/// The position errors of all constraints (as CalcPositionErrors) right after
/// ApplyTreeDisplacement: those it holds by construction (System::HeldByTreePlacement) are
/// zero to rounding and are not evaluated; the others are.
void CalcPositionErrorsAfterTreeDisplacement(const System& system, const State& state,
                                             VecX& phi);

}  // namespace sinew::engine

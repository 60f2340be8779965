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
/// satisfied to rounding (and locked coordinates, whose speeds are zero), so the projection after
/// a step only has loop joints, prescribed motions and extra constraints (couplers, ...) left to
/// correct (System::HeldByTreePlacement; CalcPositionErrors with ErrorRows::kNotHeldByTree).
/// Each direct joint's relative rotation is read from dx at the poses of `state`, its
/// coordinates from state.q.
void ApplyTreeDisplacement(const System& system, const KktSolver& kkt, const VecX& dx,
                           State& state);

}  // namespace sinew::engine

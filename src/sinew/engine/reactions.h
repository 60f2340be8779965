// Joint reaction loads from the constraint multipliers of an acceleration solve.
#pragma once

#include <sinew/engine/dynamics.h>
#include <sinew/engine/state.h>
#include <sinew/engine/system.h>

namespace sinew::engine {

/// The load that joint `joint` applies to its child body B, as [torque about M's origin;
/// force], both expressed in G (N m, N), from the multipliers of `accelerations` (computed by
/// CalcAccelerations at `state` with `kkt`). The parent receives the opposite load (about
/// the same point). Constraint loads on bodies are -J^T lambda.
SpatialVec CalcJointReaction(const System& system, const State& state,
                             const Accelerations& accelerations, const KktSolver& kkt, int joint);

}  // namespace sinew::engine

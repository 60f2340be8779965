// Constraint and joint reaction loads from the constraint multipliers of an acceleration solve.
#pragma once

#include <sinew/engine/dynamics.h>
#include <sinew/engine/state.h>
#include <sinew/engine/system.h>

#include <vector>

namespace sinew::engine {

/// The loads one constraint applies, -J^T lambda: on each body of Constraint::Bodies() (in that
/// order) [torque about the body's origin; force], both in G (N m, N), and on each coordinate
/// of Constraint::Coordinates() a generalized force (N m or N).
struct ConstraintLoads {
  std::vector<SpatialVec> on_bodies;
  VecX on_coordinates;
};

/// The loads constraint `k` (index into System::constraints()) applies at `state`, from the
/// multipliers of `accelerations` (computed by CalcAccelerations at `state` with `kkt`).
ConstraintLoads CalcConstraintLoads(const System& system, const State& state,
                                    const Accelerations& accelerations, const KktSolver& kkt,
                                    int k);

/// The load that joint `joint` applies to its child body B, as [torque about M's origin;
/// force], both expressed in G (N m, N), from the multipliers of `accelerations` (computed by
/// CalcAccelerations at `state` with `kkt`). The parent receives the opposite load (about
/// the same point).
SpatialVec CalcJointReaction(const System& system, const State& state,
                             const Accelerations& accelerations, const KktSolver& kkt, int joint);

}  // namespace sinew::engine

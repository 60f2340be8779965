// Projection of a state onto the constraint manifold: positions by Newton iterations, then
// velocities by a mass-weighted least-squares correction (both through the KKT matrix). Their
// buffers are one set per thread: once sized, a projection makes no heap allocation.
#pragma once

#include <sinew/engine/kkt.h>
#include <sinew/engine/state.h>
#include <sinew/engine/system.h>

namespace sinew::engine {

/// All constraint position errors phi (in KktSolver equation order).
VecX CalcPositionErrors(const System& system, const State& state);
/// Which constraints CalcPositionErrors evaluates: all of them, or all but those the
/// fixed-step schemes' tree update holds by construction (System::HeldByTreePlacement), whose
/// rows are then zero (right after ApplyTreeDisplacement they are, to rounding).
enum class ErrorRows { kAll, kNotHeldByTree };
/// The same into `phi` (resized; no heap use once it has the size).
void CalcPositionErrors(const System& system, const State& state, VecX& phi,
                        ErrorRows rows = ErrorRows::kAll);
/// All constraint velocity errors J v - c.
VecX CalcVelocityErrors(const System& system, const State& state, KktSolver& kkt);

/// Moves the positions (body poses, integrated coordinates) by the smallest mass-weighted
/// correction that makes every |phi| <= tolerance. Returns false when Newton does not converge
/// in `max_iterations`. Refactorizes `kkt` (the first iteration keeps a factorization made at
/// exactly these positions). Adds the factorizations it made to `*factorizations`
/// when not null.
bool ProjectPositions(const System& system, State& state, double tolerance, KktSolver& kkt,
                      int max_iterations = 10, long* factorizations = nullptr);

/// Replaces the velocities by the nearest (mass-weighted) ones with J v = c. Uses the positions
/// of `state` (refactorizes `kkt` unless it is already factorized at exactly these positions,
/// as after an rk45 step whose positions needed no projection: its last stage was evaluated
/// there).
void ProjectVelocities(const System& system, State& state, KktSolver& kkt);

/// Applies a position displacement dx in KKT velocity order: body rotations (rotation vector in
/// G) and translations, and for integrated coordinates dq = N(q) du.
void ApplyPositionDisplacement(const System& system, const KktSolver& kkt, const VecX& dx,
                               State& state);
/// Its second part alone: dq = N(q) du for the coordinates of every parameterized joint.
void AdvanceIntegratedCoordinates(const System& system, const KktSolver& kkt, const VecX& dx,
                                  State& state);

/// Moves `state` onto the constraints (positions, then velocities) with tolerance `tolerance`;
/// use before integrating a state whose coordinates were set by hand. Throws on failure.
void ProjectState(const System& system, State& state, double tolerance = 1e-12);

}  // namespace sinew::engine

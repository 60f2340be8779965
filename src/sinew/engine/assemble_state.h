// Assembly of a state onto its constraints as OpenSim assembles a model's initial state: the
// free coordinates move as little as possible from the values they hold, the locked and
// prescribed ones stay.
#pragma once

#include <sinew/engine/state.h>
#include <sinew/engine/system.h>

namespace sinew::engine {

/// Moves the free coordinates q_i of `state` (CoordinateMotion::kFree) to the q that minimizes
/// sum_i w_i (q_i - q0_i)^2 (q0 = the values on entry, w_i = Coordinate::assembly_weight)
/// subject to phi = 0 for every constraint the tree placement of bodies does not satisfy by
/// itself (loop joints and extra constraints), to |phi| <= tolerance; locked and prescribed
/// coordinates keep their values. Then places the bodies and projects the velocities
/// (mass-weighted least squares, as ProjectVelocities). Weights are in the coordinates' own
/// units (rad and m mixed, as OpenSim's AssemblySolver weighs them).
///
/// Gauss-Newton on the optimality conditions W (q - q0) + A^T lambda = 0, phi(q) = 0, with
/// A = dphi/dq by central differences of the tree placement (exact for every joint type,
/// O(h^2) = 1e-12 truncation). Throws sinew::Error naming the constraints with the largest
/// residuals when they cannot be satisfied. The default tolerance (m or rad) is ten times
/// tighter than OpenSim's default assembly_accuracy (1e-9) and equal to the projection's after
/// an integration step; in large models with redundant constraints (PushUpToesOnGround's four
/// PointConstraints) Gauss-Newton with differenced Jacobians settles near 1e-11.
void AssembleState(const System& system, State& state, double tolerance = 1e-10);

}  // namespace sinew::engine

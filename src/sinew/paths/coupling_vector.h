// How the coordinates move together when one of them moves, as OpenSim's MomentArmSolver
// decides it: a moment arm about coordinate j is -dL/dq_j with every coupled coordinate moving
// along (Rajagopal's patellae with the knees).
#pragma once

#include <sinew/kinematics/coordinate_couplers.h>
#include <sinew/model/model_spec.h>

#include <span>
#include <vector>

namespace sinew::paths {

/// The coupling vector c of coordinate j at q (MomentArmSolver::computeCouplingVector): the
/// speeds u = e_j projected onto the velocity constraints (every enforced coupler, and u = 0
/// for every locked coordinate but j itself), divided by the projected u_j; the moment arm is
/// then -c . dL/du. The projection is the minimum-norm (unit weight) correction; the result
/// does not depend on the weights when each coupler has one independent coordinate (every
/// coupler in the corpus). All NaN when the constraints leave j no motion (OpenSim divides by
/// zero there).
std::vector<double> CalcCouplingVector(const model::ModelSpec& spec,
                                       const kinematics::CoordinateCouplers& couplers,
                                       std::span<const double> q, int j);

/// The coupling vectors of `coordinates` at q (`out[k]` for coordinates[k], as
/// CalcCouplingVector gives it). The coordinates that are not locked share their constraint
/// rows: one that no row involves moves alone (e_j, without solving), one involved in a single
/// row that shares no coordinate with any other row takes that row's closed-form solution, and
/// the rows are factorized once for all the others.
void CalcCouplingVectors(const model::ModelSpec& spec,
                         const kinematics::CoordinateCouplers& couplers, std::span<const double> q,
                         std::span<const int> coordinates, std::vector<std::vector<double>>& out);

}  // namespace sinew::paths

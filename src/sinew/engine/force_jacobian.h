// Jacobians of the applied loads for implicit integration: K = df/dx and D = df/dv over the
// velocity unknowns of a KktSolver (body twists, integrated speeds), assembled from gravity
// (analytic) and each force element's blocks on its support (its own analytic blocks, or
// central differences of that element alone).
#pragma once

#include <sinew/engine/kkt.h>
#include <sinew/engine/state.h>
#include <sinew/engine/system.h>

#include <vector>

namespace sinew::engine {

/// The velocity columns (layout of `kkt`) of force element k's support, in Support() order: 6
/// per body, then one per integrated coordinate; a coordinate of a direct joint stands for its
/// joint's two bodies. Every column when the element has no Support().
std::vector<int> CalcSupportColumns(const System& system, const KktSolver& kkt, int k);

/// Force element k's loads as a vector in the layout of `kkt` (direct joints' generalized
/// forces turned into body torques).
VecX CalcForceLoadVector(const System& system, const KktSolver& kkt, const State& state, int k);

/// K and D of force element k restricted to `columns` (rows and columns), by central
/// differences of its loads over position displacements and velocities of those columns.
void CalcForceJacobiansByFiniteDifference(const System& system, const KktSolver& kkt,
                                          const State& state, int k,
                                          const std::vector<int>& columns, MatX& K, MatX& D);

/// K and D (nv x nv) of every applied load: gravity (analytic) and the force elements (their
/// CalcLoadJacobians when given, else finite differences on their support).
void CalcLoadJacobians(const System& system, const KktSolver& kkt, const State& state, MatX& K,
                       MatX& D);

}  // namespace sinew::engine

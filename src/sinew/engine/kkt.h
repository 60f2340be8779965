// The constrained linear system of the engine:
//   [ M  J^T ] [ x      ]   [ f ]
//   [ J   0  ] [ lambda ] = [ g ]
// over the velocity unknowns (body twists [w_GB; v_GB] in G, then the integrated joint speeds)
// and the constraint equations. M is the block-diagonal body mass matrix about each body origin
// (zero for joint speeds, possibly singular for massless bodies); the system as a whole is
// nonsingular when the model is well posed. The sparsity pattern never changes, so it is
// analysed once and only refactorized per evaluation (sparse LU, COLAMD ordering).
#pragma once

#include <sinew/engine/state.h>
#include <sinew/engine/system.h>
#include <sinew/engine/tree_solver.h>

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <memory>
#include <vector>

namespace sinew::engine {

/// The 6x6 spatial mass matrix of a body about its origin Bo, in G, for twists [w; v_Bo].
Eigen::Matrix<double, 6, 6> CalcBodyMassMatrix(const Body& body, const Quat& quat_GB);

/// Assembles, factorizes and solves the KKT system above for one System. Reusable across
/// states; not shareable between threads (use one per thread). Keeps a reference to the
/// System, which must outlive it.
class KktSolver {
 public:
  /// `allow_tree` false forces the general sparse LU (used to cross-check the two).
  explicit KktSolver(const System& system, bool allow_tree = true);

  int num_velocities() const { return nv_; }
  int num_equations() const { return nc_; }
  /// Column of body b's twist (-1 for ground) and of integrated coordinate c's speed.
  int BodyColumn(int b) const { return b == 0 ? -1 : 6 * (b - 1); }
  int SpeedColumn(int c) const { return 6 * (system_.num_bodies() - 1) + system_.SpeedIndex(c); }
  /// First row of constraint k among the equations.
  int EquationRow(int k) const { return row_[k]; }

  /// Evaluates M and J at `state` and factorizes. Throws sinew::Error when singular.
  void Factorize(const State& state);
  /// Solves with the last factorization: rhs = [f; g] (nv + nc). Throws sinew::Error when the
  /// solution is not accurate (singular system).
  VecX Solve(const VecX& rhs) const;

  /// True when the linear-time tree elimination is used (no loop constraints); otherwise a
  /// sparse LU of the whole matrix.
  bool uses_tree_solver() const { return tree_ != nullptr; }

  /// M * x (x has nv entries) with the M of the last Factorize.
  VecX MultiplyMass(const VecX& x) const;
  /// J * x with the J of the last Factorize.
  VecX MultiplyJacobian(const VecX& x) const;
  /// The dense matrix [M J^T; J 0] of the last Factorize (small systems; implicit schemes).
  MatX AssembleDense() const;
  /// J^T * y (y has nc entries) with the J of the last Factorize.
  VecX MultiplyJacobianTranspose(const VecX& y) const;

 private:
  const System& system_;
  int nv_ = 0, nc_ = 0;
  std::vector<int> row_;
  std::vector<std::vector<int>> columns_;  // per constraint: column of each J column (-1 = ground)
  std::vector<MatX> jacobian_;             // per constraint
  std::vector<Eigen::Matrix<double, 6, 6>> mass_;  // per body (index 0 unused)
  std::vector<Eigen::Triplet<double>> triplets_;
  Eigen::SparseMatrix<double> matrix_;
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu_;
  bool analyzed_ = false;
  std::unique_ptr<TreeKktSolver> tree_;
};

/// Packs the velocity unknowns of `state` (body twists, integrated speeds) in KKT order.
VecX GatherVelocities(const System& system, const KktSolver& kkt, const State& state);
/// Writes velocity unknowns back into `state` (body twists, integrated speeds).
void ScatterVelocities(const System& system, const KktSolver& kkt, const VecX& v, State& state);

}  // namespace sinew::engine

// The constrained linear system of the engine:
//   [ M  J^T ] [ x      ]   [ f ]
//   [ J   0  ] [ lambda ] = [ g ]
// over the velocity unknowns (body twists [w_GB; v_GB] in G, then the integrated joint speeds)
// and the constraint equations. M is the block-diagonal body mass matrix about each body origin
// (zero for joint speeds, possibly singular for massless bodies); the system as a whole is
// nonsingular when the model is well posed.
//
// Solved in linear time: the tree constraints (the joints that place bodies, and locks and
// prescribed motions of their coordinates) by the tree elimination of TreeKktSolver; every
// other constraint (loop joints, couplers, welds, any extra rows G x = g) by a Schur
// complement S = G K_T^-1 G^T, then
//   S mu = G K_T^-1 r - g,  x = K_T^-1 (r - G^T mu).
// The tree elimination is an L D L^T factorization of the symmetric K_T, so S and G K_T^-1 r
// come from forward sweeps alone, on the nodes between G's columns and ground, and a solve is
// one tree solve with mu's correction between its sweeps (TreeKktSolver::Factorize with G).
// S is symmetric positive semidefinite; it is factorized by a complete orthogonal
// decomposition that treats pivots below 1e-10 of the largest as zero, so redundant but
// consistent constraints (a planar loop of pins) get the minimum-norm multipliers instead of
// failing.
#pragma once

#include <sinew/engine/state.h>
#include <sinew/engine/system.h>
#include <sinew/engine/tree_solver.h>

#include <Eigen/LU>
#include <Eigen/QR>
#include <Eigen/SparseCore>
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
  /// kTree: the linear-time solve above. kTreeGenericNodes: the same with a generic LU for every
  /// node block, none eliminated as an articulated pivot (ArticulatedPivot), to cross-check
  /// those in tests. kDense: a dense LU with full pivoting of the whole matrix, O(n^3), to
  /// cross-check the tree solve in tests.
  enum class Method { kTree, kTreeGenericNodes, kDense };
  explicit KktSolver(const System& system, Method method = Method::kTree);

  int num_velocities() const { return nv_; }
  int num_equations() const { return nc_; }
  /// Column of body b's twist (-1 for ground) and of integrated coordinate c's speed.
  int BodyColumn(int b) const { return b == 0 ? -1 : 6 * (b - 1); }
  int SpeedColumn(int c) const { return 6 * (system_.num_bodies() - 1) + system_.SpeedIndex(c); }
  /// First row of constraint k among the equations.
  int EquationRow(int k) const { return row_[k]; }

  /// Evaluates M and J at `state` and factorizes. Throws sinew::Error when singular.
  void Factorize(const State& state);
  /// True when the last Factorize was made at exactly the positions of `state` (body poses and
  /// integrated coordinates, compared bit for bit), so that Factorize(state) would compute the
  /// same factors: M depends on the orientations only and J on the positions only (J(x), see
  /// Constraint).
  bool IsFactorizedAt(const State& state) const;
  /// Number of factorizations made so far.
  long num_factorizations() const { return num_factorizations_; }
  /// Solves with the last factorization: rhs = [f; g] (nv + nc), into x (resized; no heap use
  /// once it has its size). Throws sinew::Error when the solution is not accurate (singular
  /// system).
  void Solve(const VecX& rhs, VecX& x) const;
  /// Solve, returning the solution.
  VecX Solve(const VecX& rhs) const;

  /// The method in use.
  Method method() const { return method_; }
  /// Number of constraint equations solved by the Schur complement (not tree rows).
  int num_extra_equations() const { return ne_; }
  /// Node blocks of the tree elimination that the last Factorize eliminated as articulated
  /// pivots (0 for kTreeGenericNodes and kDense).
  int num_articulated_nodes() const { return tree_ ? tree_->num_articulated_nodes() : 0; }
  /// Node blocks of direct joints that the last Factorize eliminated as direct pivots
  /// (DirectPivot; 0 for kTreeGenericNodes and kDense).
  int num_direct_nodes() const { return tree_ ? tree_->num_direct_nodes() : 0; }

  /// The twist responses of bodies `targets` to unit loads on body `source`'s six twist
  /// columns (zero constraint right-hand side), into `out` (6 rows per target, 6 columns):
  /// block t is the part of Solve([e_j; 0]) at target t's twist, for j over source's six
  /// columns. The tree part visits only the tree paths between the bodies and ground
  /// (TreeKktSolver::SolveUnitLoadResponses); constraints outside the tree add the Schur
  /// complement's correction from Y = K_T^-1 G^T (TreeKktSolver::ExtraRowResponses) and the
  /// S^-1 that Factorize keeps:
  ///   out_t -= Y_t S^-1 Y_s^T
  /// (Y_t, Y_s: Y's rows at the target's and the source's twist; G K_T^-1 e_j = Y_s^T e_j as
  /// K_T is symmetric), one backward sweep per factorization. A rank-deficient S goes by its
  /// pseudo-inverse, exact here as unit loads are always consistent with the constraints (unlike
  /// Solve, no residual is checked). No heap use once warm. Returns false, doing nothing, for the
  /// kDense method: then use Solve. Bodies must not be ground.
  bool SolveUnitLoadResponses(int source, const std::vector<int>& targets,
                              Eigen::Ref<MatX> out) const;

  /// M * x (x has nv entries) with the M of the last Factorize.
  VecX MultiplyMass(const VecX& x) const;
  /// The same into `y`, not `x` (resized; no heap use once it has the size).
  void MultiplyMass(const VecX& x, VecX& y) const;
  /// J * x with the J of the last Factorize.
  VecX MultiplyJacobian(const VecX& x) const;
  /// The dense matrix [M J^T; J 0] of the last Factorize (small systems, cross-checks).
  MatX AssembleDense() const;
  /// The entries of [M J^T; J 0] of the last Factorize as (row, column, value) triplets,
  /// appended to `out` (entries that coincide are to be summed, as Eigen's setFromTriplets
  /// does; exact zeros of the mass blocks are left out): what the sparse implicit scheme
  /// factorizes.
  void AppendTriplets(std::vector<Eigen::Triplet<double>>& out) const;
  /// J^T * y (y has nc entries) with the J of the last Factorize.
  VecX MultiplyJacobianTranspose(const VecX& y) const;

 private:
  // Factorize without the bookkeeping of the positions.
  void FactorizeMatrices(const State& state);
  // Writes the positions Factorize depends on (body poses, integrated q) into `out`.
  void GatherPositions(const State& state, VecX& out) const;
  // Fills the tree solver's right-hand side [f; g_T] from a global one [f; g].
  void GatherTreeRhs(const VecX& rhs, VecX& tree_rhs) const;
  // Throws unless x is finite and, where the factorization is not exact by construction (the
  // dense LU, a rank-deficient Schur complement), solves the system for rhs to 1e-6 (relative).
  void CheckSolution(const VecX& rhs, const VecX& x) const;
  [[noreturn]] void ThrowSingular(double residual) const;

  const System& system_;
  Method method_;
  int nv_ = 0, nc_ = 0;
  std::vector<int> row_;
  std::vector<std::vector<int>> columns_;  // per constraint: column of each J column (-1 = ground)
  std::vector<MatX> jacobian_;             // per constraint
  std::vector<Eigen::Matrix<double, 6, 6>> mass_;  // per body (index 0 unused)
  // Tree part: constraints and their first rows in the tree solver's layout.
  std::vector<int> tree_constraints_, tree_row_;  // tree_row_ per constraint (-1: extra)
  int nc_tree_ = 0;
  std::unique_ptr<TreeKktSolver> tree_;
  // Schur part: the extra constraints, G (ne x nv), S = G K_T^-1 G^T.
  std::vector<int> extra_constraints_, extra_row_;  // extra_row_ per constraint (-1: tree)
  int ne_ = 0;
  MatX G_, S_;
  Eigen::CompleteOrthogonalDecomposition<MatX> schur_;  // tells S's rank
  Eigen::PartialPivLU<MatX> schur_lu_;                  // inverts a full-rank S in place
  MatX schur_inverse_;  // S^-1, or its pseudo-inverse when S is rank-deficient (ne x ne, small)
  bool residual_check_ = true;  // CheckSolution computes the residual (see there)
  // The positions of the last successful Factorize and a buffer to compare them with.
  bool factorized_ = false;
  VecX factorized_positions_;
  mutable VecX positions_;
  long num_factorizations_ = 0;
  // Buffers of Solve, so that it allocates nothing (g_: the extra rows' right-hand side).
  mutable VecX tree_rhs_, y_, g_, mu_, residual_;
  // Buffer of SolveUnitLoadResponses: S^-1 Y_s^T (ne x 6).
  mutable Eigen::Matrix<double, Eigen::Dynamic, 6> unit_mu_;
  // Dense method.
  Eigen::FullPivLU<MatX> dense_;
};

/// Packs the velocity unknowns of `state` (body twists, integrated speeds) in KKT order.
VecX GatherVelocities(const System& system, const KktSolver& kkt, const State& state);
/// The same into `v`, of size KktSolver::num_velocities() (no heap use).
void GatherVelocities(const System& system, const KktSolver& kkt, const State& state,
                      Eigen::Ref<VecX> v);
/// Writes velocity unknowns back into `state` (body twists, integrated speeds).
void ScatterVelocities(const System& system, const KktSolver& kkt, Eigen::Ref<const VecX> v,
                       State& state);

}  // namespace sinew::engine

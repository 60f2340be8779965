// Linear-time solution of the KKT system of a tree (no loop constraints): a block elimination
// that follows the tree from the leaves to ground. Each supernode holds one outboard body's
// twist, its joint's speeds and the multipliers of the joint's and its coordinates' constraint
// rows; its pivot block is the KKT matrix of that body, with its subtree's articulated inertia,
// on a fixed base, which is invertible exactly when the model is well posed (massless bodies
// are fine when their joints take away the directions without inertia).
#pragma once

#include <sinew/engine/articulated_pivot.h>
#include <sinew/engine/direct_pivot.h>
#include <sinew/math/types.h>

#include <Eigen/LU>
#include <span>
#include <vector>

namespace sinew::engine {

class System;

/// Tree-ordered block elimination of [M J_T^T; J_T 0] over the velocity unknowns and the rows of
/// the tree constraints only (the joints that place bodies and constraints on one such joint's
/// coordinates); KktSolver adds the other constraints by a Schur complement.
class TreeKktSolver {
 public:
  /// `body_columns[b]`, `speed_columns[c]` give velocity indices; `tree_constraints` the
  /// constraints (indices into System::constraints()) it takes, `equation_rows[k]` the first
  /// row of constraint k among them (the solver's vectors are [velocities; their rows]);
  /// `columns[k]` the velocity column of each Jacobian column of constraint k (-1 for ground).
  /// With `articulated`, the blocks of parameterized joints are eliminated as articulated pivots
  /// (ArticulatedPivot) and those of direct joints as direct pivots (DirectPivot); without,
  /// every block by a generic LU.
  TreeKktSolver(const System& system, int nv, const std::vector<int>& body_columns,
                const std::vector<int>& speed_columns, const std::vector<int>& tree_constraints,
                const std::vector<int>& equation_rows, const std::vector<std::vector<int>>& columns,
                bool articulated = true);

  /// Factorizes with body mass matrices `mass[b]` and constraint Jacobians `jacobian[k]`.
  /// Throws sinew::Error when a pivot block is singular.
  void Factorize(const std::vector<Eigen::Matrix<double, 6, 6>>& mass,
                 const std::vector<MatX>& jacobian);
  /// Solves with the last factorization: rhs and x are [velocities; tree rows] (x is resized;
  /// no heap use once it has its size).
  void Solve(const VecX& rhs, VecX& x) const;
  /// Extra constraint rows G (ne of them, over the velocity unknowns only) that the caller
  /// eliminates by a Schur complement on top of the tree; `columns` are the velocity columns
  /// where G may be nonzero. Call once, before the first Factorize with G.
  void SetExtraRowColumns(int ne, const std::vector<int>& columns);
  /// Factorize, and with it S = G K^-1 G^T (ne x ne) into `S` for the extra rows G. The
  /// tree's block elimination is an L D L^T factorization of the symmetric K (D the node blocks
  /// K_k), so
  ///   S = (L^-1 G^T)^T D^-1 (L^-1 G^T) = sum over nodes of F_k^T K_k^-1 F_k,
  /// F = L^-1 G^T the forward sweep of G^T's columns, zero outside the nodes between G's
  /// columns and ground: only those nodes are visited, each as the elimination passes it, and
  /// F_k and Z_k = K_k^-1 F_k are kept for the solves. No heap use once warm.
  void Factorize(const std::vector<Eigen::Matrix<double, 6, 6>>& mass,
                 const std::vector<MatX>& jacobian, const MatX& G, MatX& S);
  /// Solves [K G^T; G 0] [x; mu] = [rhs; e] with the last Factorize with G and S^-1 (or a
  /// pseudo-inverse) in `S_inverse`, as one tree solve: after the forward sweep gives z =
  /// D^-1 L^-1 rhs, mu = S^-1 (sum F_k^T z_k - e) and z_k -= Z_k mu on the extra rows' nodes,
  /// then the backward sweep. x as in Solve; mu resized to ne.
  void SolveWithExtraRows(const VecX& rhs, const VecX& e, const MatX& S_inverse, VecX& x,
                          VecX& mu) const;
  /// Y = K^-1 G^T ((nv + tree rows) x ne) of the last Factorize with G, made by one backward
  /// sweep on the first call after it.
  const MatX& ExtraRowResponses() const;
  /// Node blocks the last Factorize eliminated as articulated pivots.
  int num_articulated_nodes() const;
  /// Node blocks the last Factorize eliminated as direct pivots (the rest by generic LU).
  int num_direct_nodes() const;
  /// The twist responses of bodies `targets` to the six unit loads on body `source`'s twist
  /// columns (zero constraint right-hand side): block t of `out` (rows 6 t to 6 t + 5, 6
  /// columns) is the part of Solve([e_j; 0]) at target t's twist, for j over source's six
  /// columns. Visits only the nodes between the bodies and ground (a path per body, not the
  /// whole tree): what contact rows need of the constrained inverse mass. No heap use once
  /// warm. Bodies must not be ground.
  void SolveUnitLoadResponses(int source, const std::vector<int>& targets,
                              Eigen::Ref<MatX> out) const;

 private:
  struct Entry {
    int row, col;  // local row and local column (col < 0: inboard body column -1 - col)
    int jac_row, jac_col;
  };
  // Consecutive Jacobian columns of one constraint that land in consecutive local columns (or
  // inboard body columns): copied into the node block as one block.
  struct ColumnRun {
    int constraint;           // its index in System::constraints()
    int first_row, rows;      // the local rows of the constraint's equations
    int jac_col, col, width;  // col as in Entry
  };
  // Node blocks never exceed 24 rows (6 twist + 6 speeds + 6 joint rows + 6 coordinate rows):
  // fixed-capacity matrices keep them off the heap.
  static constexpr int kMaxNode = 24;
  using NodeMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxNode, kMaxNode>;
  using NodeVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxNode, 1>;

 public:
  /// The largest supernode the solver takes (larger ones: use the sparse LU).
  static constexpr int max_node_size() { return kMaxNode; }

 private:
  // How a node's block is eliminated.
  enum class Pivot { kLu, kArticulated, kDirect };
  struct Node {
    int body = 0;             // outboard body
    int parent = -1;          // node of the inboard body (-1: ground)
    int num_speeds = 0;       // joint speeds among the unknowns (after the 6 twist entries)
    Pivot fits = Pivot::kLu;  // the closed form the block's layout allows (at construction)
    Pivot used = Pivot::kLu;  // what the last Factorize used
    std::vector<int> constraints;
    std::vector<std::vector<Entry>> entries;  // per constraint: where its J entries go
    int first_run = 0, end_run = 0;           // the same, by runs of columns, in runs_
    int size = 0;                             // n: its unknowns
    int row = 0;     // its first row in the node-ordered arrays (the earlier nodes' sizes)
    int block = 0;   // where its K starts in blocks_ (the earlier nodes' n^2)
    int pivot = -1;  // its closed-form pivot in articulated_ or direct_ (by `fits`), or -1
    // Who writes its mass block in the leaves-first pass: itself when it has no children, else
    // the child eliminated first (its highest-numbered one), before adding to it.
    bool leaf = true;
    bool writes_parent_mass = false;
  };
  // A node's pivot block K (n x n), coupling C to the inboard body's twist (n x 6), W = K^-1 C,
  // and its part of the solves' vector z, as views of the dense arrays below.
  using BlockView = Eigen::Map<MatX>;
  using ConstBlockView = Eigen::Map<const MatX>;
  using CouplingView = Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, 6>>;
  using ConstCouplingView = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 6>>;
  BlockView K(int k) { return {blocks_.data() + nodes_[k].block, nodes_[k].size, nodes_[k].size}; }
  CouplingView C(int k) { return {couplings_.data() + 6 * nodes_[k].row, nodes_[k].size, 6}; }
  ConstCouplingView C(int k) const {
    return {couplings_.data() + 6 * nodes_[k].row, nodes_[k].size, 6};
  }
  CouplingView W(int k) { return {responses_.data() + 6 * nodes_[k].row, nodes_[k].size, 6}; }
  ConstCouplingView W(int k) const {
    return {responses_.data() + 6 * nodes_[k].row, nodes_[k].size, 6};
  }
  auto Z(int k) const { return z_.segment(nodes_[k].row, nodes_[k].size); }
  // A node's F_k and Z_k of the extra rows (n x ne; zero off their nodes).
  BlockView ExtraF(int k) { return {extra_F_.data() + nodes_[k].row * ne_, nodes_[k].size, ne_}; }
  ConstBlockView ExtraF(int k) const {
    return {extra_F_.data() + nodes_[k].row * ne_, nodes_[k].size, ne_};
  }
  BlockView ExtraZ(int k) { return {extra_Z_.data() + nodes_[k].row * ne_, nodes_[k].size, ne_}; }
  ConstBlockView ExtraZ(int k) const {
    return {extra_Z_.data() + nodes_[k].row * ne_, nodes_[k].size, ne_};
  }
  // Whether node's block has the articulated layout: a parameterized joint's 6 rows first, then
  // rows on the joint speeds only.
  bool FitsArticulatedPivot(const Node& node, int joint) const;
  // Whether node's block is a direct joint's alone: the twist and the joint's rows.
  bool FitsDirectPivot(const Node& node, int joint) const;
  // The node's constraint rows, its last rows: the coupling C is zero above them.
  static int NumConstraintRows(const Node& node) { return node.size - 6 - node.num_speeds; }
  // Both Factorize forms (G and S null without extra rows).
  void FactorizeTree(const std::vector<Eigen::Matrix<double, 6, 6>>& mass,
                     const std::vector<MatX>& jacobian, const MatX* G, MatX* S);
  // The extra rows' F from G, S zeroed; then, node by node as the elimination passes them
  // (leaves first), Z_k, the parent's F and S's term.
  void StartExtraRows(const MatX& G, MatX& S);
  void EliminateExtraRows(int k, MatX& S);
  // Node k's mass block from its body's mass matrix.
  void PlaceMass(int k, const std::vector<Eigen::Matrix<double, 6, 6>>& mass);
  // Node k's constraint entries from the Jacobians (its column runs).
  void FillNode(int k, const std::vector<MatX>& jacobian);
  // Factorizes node k's block (the articulated pivot where it applies, else the LU).
  void FactorizeNode(int k);
  // x = K^-1 x with node k's factorization.
  template <typename X>
  void SolveNode(int k, X& x) const {
    const Node& node = nodes_[k];
    switch (node.used) {
      case Pivot::kArticulated:
        articulated_[node.pivot].SolveInPlace(x);
        break;
      case Pivot::kDirect:
        direct_[node.pivot].SolveInPlace(x);
        break;
      case Pivot::kLu:  // (Eigen's LU solves in place when x is its own right-hand side)
        x = lu_[k].solve(x);
        break;
    }
  }
  // The two halves of Solve on z_: the forward sweep leaves z = D^-1 L^-1 rhs per node,
  // the backward one turns z into x.
  void SolveForward(const VecX& rhs) const;
  void SolveBackward(VecX& x) const;
  // Node k's block solve on every column of x.
  void SolveNodeColumns(int k, Eigen::Ref<MatX> x) const;
  const System& system_;
  Eigen::Index size_;        // velocities and tree rows: the length of rhs and x
  std::vector<Node> nodes_;  // in tree order (a node after its parent)
  // The nodes' matrices and factors, apart from the nodes, each kind in one dense array in node
  // order, so that a sweep walks memory in order: on a long chain they outgrow the cache, and
  // nodes holding every kind (each sized for the largest block) spread what a solve reads over
  // 16 kB per node, which the hardware's prefetching does not follow.
  std::vector<double> blocks_;                       // each node's K, n x n (Node::block)
  std::vector<double> couplings_;                    // each node's C, n x 6 (Node::row)
  std::vector<double> responses_;                    // each node's W, n x 6
  std::vector<Eigen::PartialPivLU<NodeMatrix>> lu_;  // per node, the generic LU (the fallback)
  std::vector<ArticulatedPivot> articulated_;        // the nodes that fit one (Node::pivot)
  std::vector<DirectPivot> direct_;                  // likewise
  std::vector<ColumnRun> runs_;     // every node's, in node order (Node::first_run)
  std::vector<int> node_of_body_;   // per System body, its node (-1: ground)
  mutable VecX z_;                  // the solves' vector, node by node (Node::row)
  std::vector<int> global_of_row_;  // the global index of each of z_'s rows
  // Node k's part of global_of_row_: the global index of each of its local unknowns.
  std::span<const int> Global(int k) const {
    return {global_of_row_.data() + nodes_[k].row, static_cast<size_t>(nodes_[k].size)};
  }
  // SolveUnitLoadResponses: per node six right-hand sides, and marks of the nodes a call has
  // visited forward (on the source's path) and backward (solved), by call number.
  using NodeBlock = Eigen::Matrix<double, Eigen::Dynamic, 6, 0, kMaxNode, 6>;
  mutable std::vector<NodeBlock> unit_blocks_;
  mutable std::vector<long> forward_mark_, backward_mark_;
  mutable std::vector<int> stack_;
  mutable long calls_ = 0;
  // Extra rows (SetExtraRowColumns): the nodes between their columns and ground, leaves first,
  // and per node (ExtraF, ExtraZ: zero off those nodes) F_k and Z_k = K_k^-1 F_k.
  int ne_ = 0;
  std::vector<int> extra_nodes_;
  std::vector<double> extra_F_, extra_Z_;     // F_k, Z_k node by node (at Node::row times ne)
  mutable std::vector<MatX> extra_Y_blocks_;  // ExtraRowResponses' per-node rows
  mutable MatX extra_Y_;
  mutable VecX extra_g_;
  mutable bool extra_Y_current_ = false;
  mutable NodeVector column_scratch_;
};

}  // namespace sinew::engine

#include <sinew/common/error.h>
#include <sinew/engine/system.h>
#include <sinew/engine/tree_solver.h>

#include <string>
#include <utility>

namespace sinew::engine {

TreeKktSolver::TreeKktSolver(const System& system, int nv, const std::vector<int>& body_columns,
                             const std::vector<int>& speed_columns,
                             const std::vector<int>& tree_constraints,
                             const std::vector<int>& equation_rows,
                             const std::vector<std::vector<int>>& columns, bool articulated)
    : system_(system), size_(nv) {
  const auto& constraints = system.constraints();
  for (int k : tree_constraints) size_ += constraints[k]->NumEquations();
  const int num_joints = static_cast<int>(system.joints().size());
  std::vector<int> node_of_joint(num_joints, -1), node_of_body(system.num_bodies(), -1);
  std::vector<std::vector<ColumnRun>> node_runs(system.tree_order().size());
  // Each node's global indices as they are found (flattened into global_of_row_ below).
  std::vector<std::vector<int>> node_global;
  for (int j : system.tree_order()) {
    const Joint& joint = system.joints()[j];
    Node node;
    node.body = system.IsReversed(j) ? joint.parent : joint.child;
    const int inboard = system.IsReversed(j) ? joint.child : joint.parent;
    node.parent = inboard == 0 ? -1 : node_of_body[inboard];
    std::vector<int>& global = node_global.emplace_back();
    for (int i = 0; i < 6; ++i) global.push_back(body_columns[node.body] + i);
    for (int c : joint.coordinates) {
      if (system.IsIntegrated(c)) global.push_back(speed_columns[c]);
    }
    node.num_speeds = static_cast<int>(global.size()) - 6;
    node.size = static_cast<int>(global.size());
    node_of_joint[j] = static_cast<int>(nodes_.size());
    node_of_body[node.body] = node_of_joint[j];
    nodes_.push_back(std::move(node));
  }
  node_of_body_ = node_of_body;
  // Constraint rows: joint j's own, and coordinate constraints of its coordinates.
  for (int k : tree_constraints) {
    int joint = -1;
    if (k < num_joints) {
      joint = k;
    } else {
      const std::vector<int> coords = constraints[k]->Coordinates();
      if (!constraints[k]->Bodies().empty() || coords.empty()) {
        throw Error("engine: TreeKktSolver cannot take loop constraints");
      }
      joint = system.coordinates()[coords[0]].joint;
    }
    if (node_of_joint[joint] < 0) throw Error("engine: TreeKktSolver cannot take loop joints");
    Node& node = nodes_[node_of_joint[joint]];
    std::vector<int>& global = node_global[node_of_joint[joint]];
    node.constraints.push_back(k);
    const int first_row = static_cast<int>(global.size());
    for (int r = 0; r < constraints[k]->NumEquations(); ++r) {
      global.push_back(nv + equation_rows[k] + r);
    }
    node.size = static_cast<int>(global.size());
    const int inboard = node.parent < 0 ? 0 : nodes_[node.parent].body;
    std::vector<Entry> entries;
    for (int r = 0; r < constraints[k]->NumEquations(); ++r) {
      for (size_t jc = 0; jc < columns[k].size(); ++jc) {
        const int g = columns[k][jc];
        if (g < 0) continue;  // ground
        Entry e{first_row + r, 0, r, static_cast<int>(jc)};
        int local = -1;
        for (int i = 0; i < first_row; ++i) {
          if (global[i] == g) local = i;
        }
        if (local >= 0) {
          e.col = local;
        } else if (inboard > 0 && g >= body_columns[inboard] && g < body_columns[inboard] + 6) {
          e.col = -1 - (g - body_columns[inboard]);
        } else {
          throw Error("engine: a joint constraint reaches beyond its two bodies");
        }
        entries.push_back(e);
      }
    }
    // Runs of columns, from the first row's entries (every row maps its columns alike).
    std::vector<ColumnRun>& runs = node_runs[node_of_joint[joint]];
    const size_t first_run = runs.size();
    for (const Entry& e : entries) {
      if (e.jac_row != 0) break;
      if (runs.size() > first_run) {
        ColumnRun& last = runs.back();
        const bool same_side = (last.col >= 0) == (e.col >= 0);
        const int next = last.col >= 0 ? last.col + last.width : last.col - last.width;
        if (same_side && e.jac_col == last.jac_col + last.width && e.col == next) {
          ++last.width;
          continue;
        }
      }
      runs.push_back({k, first_row, constraints[k]->NumEquations(), e.jac_col, e.col, 1});
    }
    node.entries.push_back(std::move(entries));
  }
  for (int j = 0; j < num_joints; ++j) {
    if (!articulated || node_of_joint[j] < 0) continue;
    Node& node = nodes_[node_of_joint[j]];
    if (FitsArticulatedPivot(node, j)) {
      node.fits = Pivot::kArticulated;
    } else if (FitsDirectPivot(node, j)) {
      node.fits = Pivot::kDirect;
    }
  }
  lu_.resize(nodes_.size());
  int rows = 0, block = 0;
  for (Node& node : nodes_) {
    const int n = node.size;
    if (n > kMaxNode) throw Error("engine: a joint block is too large for the tree solver");
    node.row = rows;
    node.block = block;
    rows += n;
    block += n * n;
    if (node.fits == Pivot::kArticulated) {
      node.pivot = static_cast<int>(articulated_.size());
      articulated_.emplace_back();
    } else if (node.fits == Pivot::kDirect) {
      node.pivot = static_cast<int>(direct_.size());
      direct_.emplace_back();
    }
  }
  for (size_t k = 0; k < nodes_.size(); ++k) {
    Node& node = nodes_[k];
    global_of_row_.insert(global_of_row_.end(), node_global[k].begin(), node_global[k].end());
    node.first_run = static_cast<int>(runs_.size());
    runs_.insert(runs_.end(), node_runs[k].begin(), node_runs[k].end());
    node.end_run = static_cast<int>(runs_.size());
  }
  for (size_t k = nodes_.size(); k-- > 0;) {
    Node& node = nodes_[k];
    if (node.parent < 0) continue;
    node.writes_parent_mass = nodes_[node.parent].leaf;  // no child of it came up before
    nodes_[node.parent].leaf = false;
  }
  blocks_.assign(block, 0.0);
  couplings_.assign(6 * static_cast<size_t>(rows), 0.0);
  responses_.assign(6 * static_cast<size_t>(rows), 0.0);
  z_.setZero(rows);
}

void TreeKktSolver::Factorize(const std::vector<Eigen::Matrix<double, 6, 6>>& mass,
                              const std::vector<MatX>& jacobian) {
  FactorizeTree(mass, jacobian, nullptr, nullptr);
}

void TreeKktSolver::Factorize(const std::vector<Eigen::Matrix<double, 6, 6>>& mass,
                              const std::vector<MatX>& jacobian, const MatX& G, MatX& S) {
  FactorizeTree(mass, jacobian, &G, &S);
}

void TreeKktSolver::FactorizeTree(const std::vector<Eigen::Matrix<double, 6, 6>>& mass,
                                  const std::vector<MatX>& jacobian, const MatX* G, MatX* S) {
  if (G) StartExtraRows(*G, *S);
  // Leaves first: each node's block is filled and eliminated into its parent's body block, and
  // the extra rows' F and Z formed, in one pass, so that a node's matrices are still in the
  // cache from one use to the next (on a 1000-link chain the nodes outgrow it). A node's mass
  // block is written when it comes up if it is a leaf, else when its first child does.
  size_t next_extra = 0;
  for (int k = static_cast<int>(nodes_.size()); k-- > 0;) {
    const Node& node = nodes_[k];
    if (node.leaf) PlaceMass(k, mass);
    FillNode(k, jacobian);
    FactorizeNode(k);
    if (G && next_extra < extra_nodes_.size() && extra_nodes_[next_extra] == k) {
      EliminateExtraRows(k, *S);
      ++next_extra;
    }
    if (node.parent < 0) continue;
    if (node.writes_parent_mass) PlaceMass(node.parent, mass);
    auto parent_block = K(node.parent).topLeftCorner<6, 6>();
    const ConstCouplingView C = std::as_const(*this).C(k);
    CouplingView W = this->W(k);
    Eigen::Matrix<double, 6, 6> CtW;
    if (node.used == Pivot::kArticulated) {
      // Closed form: C is J_P in the joint rows and zero elsewhere.
      const Eigen::Matrix<double, 6, 6> J_P = C.middleRows<6>(6 + node.num_speeds);
      articulated_[node.pivot].SolveCoupling(J_P, W, CtW);
      parent_block -= CtW;
    } else if (node.used == Pivot::kDirect) {
      direct_[node.pivot].SolveCoupling(C.bottomRows(NumConstraintRows(node)), W, CtW);
      parent_block -= CtW;
    } else {
      W = C;
      SolveNode(k, W);
      // C is zero in the twist and speed rows; a coefficient-wise product on the constraint
      // rows instead of Eigen's blocked GEMM, which these small sizes do not repay.
      const int rows = NumConstraintRows(node);
      parent_block.noalias() -= C.bottomRows(rows).transpose().lazyProduct(W.bottomRows(rows));
    }
  }
}

void TreeKktSolver::PlaceMass(int k, const std::vector<Eigen::Matrix<double, 6, 6>>& mass) {
  K(k).topLeftCorner<6, 6>() = mass[nodes_[k].body];
}

void TreeKktSolver::FillNode(int k, const std::vector<MatX>& jacobian) {
  // Every entry outside the mass block and the constraint entries stays zero from construction.
  const Node& node = nodes_[k];
  BlockView K = this->K(k);
  CouplingView C = this->C(k);
  for (int r = node.first_run; r < node.end_run; ++r) {
    const ColumnRun& run = runs_[r];
    const MatX& J = jacobian[run.constraint];
    if (run.rows == 6 && run.width == 6) {
      // A joint's six rows on a whole twist (the common run), with fixed sizes.
      const auto block = J.middleCols<6>(run.jac_col);
      if (run.col >= 0) {
        K.block<6, 6>(run.first_row, run.col) = block;
      } else {
        C.block<6, 6>(run.first_row, -1 - run.col) = block;
      }
      continue;
    }
    const auto block = J.middleCols(run.jac_col, run.width);
    if (run.col >= 0) {
      // The lower triangle only: the pivots read no more, and the LU fills the upper
      // triangle from it when it is used (FactorizeNode).
      K.block(run.first_row, run.col, run.rows, run.width) = block;
    } else {
      // Inboard columns run downwards from -1 - col.
      C.block(run.first_row, -1 - run.col, run.rows, run.width) = block;
    }
  }
}

int TreeKktSolver::num_articulated_nodes() const {
  int n = 0;
  for (const Node& node : nodes_) n += node.used == Pivot::kArticulated ? 1 : 0;
  return n;
}

int TreeKktSolver::num_direct_nodes() const {
  int n = 0;
  for (const Node& node : nodes_) n += node.used == Pivot::kDirect ? 1 : 0;
  return n;
}

bool TreeKktSolver::FitsArticulatedPivot(const Node& node, int joint) const {
  const auto& constraints = system_.constraints();
  if (system_.joints()[joint].form != JointForm::kParameterized || node.constraints.empty() ||
      node.constraints[0] != joint || constraints[joint]->NumEquations() != 6) {
    return false;
  }
  const int num_rows = node.size - 12 - node.num_speeds;
  if (num_rows < 0 || (node.num_speeds == 0 && num_rows > 0)) return false;
  for (size_t i = 1; i < node.constraints.size(); ++i) {
    for (const Entry& e : node.entries[i]) {
      if (e.col < 6 || e.col >= 6 + node.num_speeds) return false;
    }
  }
  return true;
}

bool TreeKktSolver::FitsDirectPivot(const Node& node, int joint) const {
  return system_.joints()[joint].form != JointForm::kParameterized && node.num_speeds == 0 &&
         node.constraints.size() == 1 && node.constraints[0] == joint;
}

void TreeKktSolver::FactorizeNode(int k) {
  Node& node = nodes_[k];
  BlockView K = this->K(k);
  node.used = Pivot::kLu;
  if (node.fits == Pivot::kArticulated && articulated_[node.pivot].Factorize(K, node.num_speeds)) {
    node.used = Pivot::kArticulated;
    return;
  }
  if (node.fits == Pivot::kDirect && direct_[node.pivot].Factorize(K)) {
    node.used = Pivot::kDirect;
    return;
  }
  // Factorize wrote the constraint rows' entries below the diagonal only: J^T from J.
  const int first = 6 + node.num_speeds, rows = NumConstraintRows(node);
  K.block(0, first, first, rows) = K.block(first, 0, rows, first).transpose();
  lu_[k].compute(K);
  // Partial pivoting puts each column's largest entry on U's diagonal: a pivot that is tiny
  // next to the largest one means a singular block.
  const auto pivots = lu_[k].matrixLU().diagonal().cwiseAbs();
  const double rcond = pivots.minCoeff() / pivots.maxCoeff();
  if (!(rcond > 1e-14)) {
    throw Error({}, system_.bodies()[node.body].name,
                "engine: the equations of motion are singular at this body (rcond " +
                    std::to_string(rcond) +
                    "): a body without mass or inertia in a direction its joint leaves free?");
  }
}

namespace {

// parent -= C_R^T z_R, C_R and z_R the last R rows of a node's coupling and vector (the
// constraint rows: C is zero above them), with R known at compile time.
template <int R, typename CMatrix, typename ZVector, typename PVector>
void SubtractCouplingRows(const CMatrix& C, const ZVector& z, PVector parent) {
  parent.noalias() -= C.template bottomRows<R>().transpose().lazyProduct(z.template tail<R>());
}

// z -= W x_P for a node of N rows known at compile time.
template <int N, typename WMatrix, typename ZVector, typename PVector>
void SubtractParentResponse(const WMatrix& W, const PVector& x_parent, ZVector& z) {
  z.template head<N>().noalias() -= W.template topRows<N>().lazyProduct(x_parent);
}

}  // namespace

void TreeKktSolver::Solve(const VecX& rhs, VecX& x) const {
  SolveForward(rhs);
  SolveBackward(x);
}

void TreeKktSolver::SolveForward(const VecX& rhs) const {
  for (size_t r = 0; r < global_of_row_.size(); ++r) z_[r] = rhs[global_of_row_[r]];
  // Forward: z_k = K_k^-1 r_k, parent's body rows lose C^T z_k. The common sizes (a direct
  // joint's 3 to 6 rows, a parameterized joint's 6) with fixed sizes: Eigen's products of run-time
  // size cost more than their arithmetic here, and these walks are most of a projection's Newton
  // iteration on a long chain.
  for (int k = static_cast<int>(nodes_.size()); k-- > 0;) {
    const Node& node = nodes_[k];
    auto z = Z(k);
    if (node.used == Pivot::kArticulated) {
      // (its fixed-size solves run faster on a vector of their own than on a view of z_)
      NodeVector z_k = z;
      SolveNode(k, z_k);
      z = z_k;
    } else {
      SolveNode(k, z);
    }
    if (node.parent < 0) continue;
    const int rows = NumConstraintRows(node);
    auto parent_rows = Z(node.parent).head<6>();
    const ConstCouplingView C = this->C(k);
    switch (rows) {
      case 3:
        SubtractCouplingRows<3>(C, z, parent_rows);
        break;
      case 4:
        SubtractCouplingRows<4>(C, z, parent_rows);
        break;
      case 5:
        SubtractCouplingRows<5>(C, z, parent_rows);
        break;
      case 6:
        SubtractCouplingRows<6>(C, z, parent_rows);
        break;
      default:
        parent_rows.noalias() -= C.bottomRows(rows).transpose().lazyProduct(z.tail(rows));
        break;
    }
  }
}

void TreeKktSolver::SolveBackward(VecX& x) const {
  // Backward: x_k = z_k - W_k x_parent (a direct joint's node has 9 to 12 rows).
  x.resize(size_);
  for (int k = 0; k < static_cast<int>(nodes_.size()); ++k) {
    const Node& node = nodes_[k];
    if (node.parent < 0) continue;
    auto z = Z(k);
    const auto x_parent = Z(node.parent).head<6>();
    const ConstCouplingView W = this->W(k);
    switch (z.size()) {
      case 9:
        SubtractParentResponse<9>(W, x_parent, z);
        break;
      case 10:
        SubtractParentResponse<10>(W, x_parent, z);
        break;
      case 11:
        SubtractParentResponse<11>(W, x_parent, z);
        break;
      case 12:
        SubtractParentResponse<12>(W, x_parent, z);
        break;
      default:
        z.noalias() -= W.lazyProduct(x_parent);
        break;
    }
  }
  for (size_t r = 0; r < global_of_row_.size(); ++r) x[global_of_row_[r]] = z_[r];
}

void TreeKktSolver::SolveUnitLoadResponses(int source, const std::vector<int>& targets,
                                           Eigen::Ref<MatX> out) const {
  const size_t n = nodes_.size();
  if (unit_blocks_.size() != n) {
    unit_blocks_.resize(n);
    forward_mark_.assign(n, 0);
    backward_mark_.assign(n, 0);
  }
  const long call = ++calls_;
  // Forward, along the path from the source to ground: z_k = K_k^-1 r_k, and the parent's body
  // rows lose C^T z_k (every other node's right-hand side stays zero).
  int k = node_of_body_[source];
  unit_blocks_[k].setZero(nodes_[k].size, 6);
  unit_blocks_[k].topRows<6>().setIdentity();
  while (k >= 0) {
    forward_mark_[k] = call;
    SolveNode(k, unit_blocks_[k]);
    const int parent = nodes_[k].parent;
    if (parent >= 0) {
      unit_blocks_[parent].setZero(nodes_[parent].size, 6);
      const int rows = NumConstraintRows(nodes_[k]);
      unit_blocks_[parent].topRows<6>().noalias() -=
          C(k).bottomRows(rows).transpose().lazyProduct(unit_blocks_[k].bottomRows(rows));
    }
    k = parent;
  }
  // Backward, from ground down to each target: x_k = z_k - W_k x_parent (z_k = 0 off the
  // source's path).
  for (size_t t = 0; t < targets.size(); ++t) {
    stack_.clear();
    for (int j = node_of_body_[targets[t]]; j >= 0 && backward_mark_[j] != call;
         j = nodes_[j].parent) {
      stack_.push_back(j);
    }
    for (size_t i = stack_.size(); i-- > 0;) {
      const int j = stack_[i];
      if (forward_mark_[j] != call) unit_blocks_[j].setZero(nodes_[j].size, 6);
      const int parent = nodes_[j].parent;
      if (parent >= 0)
        unit_blocks_[j].noalias() -= W(j).lazyProduct(unit_blocks_[parent].topRows<6>());
      backward_mark_[j] = call;
    }
    out.block<6, 6>(6 * static_cast<Eigen::Index>(t), 0) =
        unit_blocks_[node_of_body_[targets[t]]].topRows<6>();
  }
}

void TreeKktSolver::SetExtraRowColumns(int ne, const std::vector<int>& columns) {
  ne_ = ne;
  std::vector<int> node_of_global;
  for (size_t k = 0; k < nodes_.size(); ++k) {
    for (int g : Global(static_cast<int>(k))) {
      if (g >= static_cast<int>(node_of_global.size())) node_of_global.resize(g + 1, -1);
      node_of_global[g] = static_cast<int>(k);
    }
  }
  std::vector<char> on_path(nodes_.size(), 0);
  for (int g : columns) {
    if (g < 0 || g >= static_cast<int>(node_of_global.size()) || node_of_global[g] < 0) {
      throw Error("engine: an extra constraint row reaches a velocity outside the tree");
    }
    for (int k = node_of_global[g]; k >= 0 && !on_path[k]; k = nodes_[k].parent) on_path[k] = 1;
  }
  extra_nodes_.clear();
  for (size_t k = nodes_.size(); k-- > 0;) {
    if (on_path[k]) extra_nodes_.push_back(static_cast<int>(k));
  }
  extra_F_.assign(global_of_row_.size() * ne, 0.0);
  extra_Z_.assign(global_of_row_.size() * ne, 0.0);
  extra_Y_current_ = false;
}

void TreeKktSolver::SolveNodeColumns(int k, Eigen::Ref<MatX> x) const {
  // Column by column: the pivots' one-column solves have every size fixed, which costs less
  // than their multi-column forms with a run-time column count.
  for (Eigen::Index c = 0; c < x.cols(); ++c) {
    column_scratch_ = x.col(c);
    SolveNode(k, column_scratch_);
    x.col(c) = column_scratch_;
  }
}

void TreeKktSolver::StartExtraRows(const MatX& G, MatX& S) {
  // F starts as G^T on each node's velocity unknowns (zero on its constraint rows).
  for (int k : extra_nodes_) {
    const Node& node = nodes_[k];
    BlockView F = ExtraF(k);
    F.setZero();
    const std::span<const int> global = Global(k);
    for (int i = 0; i < 6 + node.num_speeds; ++i) F.row(i) = G.col(global[i]).transpose();
  }
  S.setZero(ne_, ne_);
  extra_Y_current_ = false;
}

void TreeKktSolver::EliminateExtraRows(int k, MatX& S) {
  // Leaves first, as Solve's forward sweep: Z_k = K_k^-1 F_k, the parent's twist rows of F lose
  // C^T Z_k (C is zero above the constraint rows).
  const Node& node = nodes_[k];
  BlockView Zk = ExtraZ(k);
  Zk = ExtraF(k);
  SolveNodeColumns(k, Zk);
  if (node.parent >= 0) {
    const int rows = NumConstraintRows(node);
    ExtraF(node.parent).topRows<6>().noalias() -=
        C(k).bottomRows(rows).transpose().lazyProduct(Zk.bottomRows(rows));
  }
  S.noalias() += ExtraF(k).transpose().lazyProduct(Zk);
}

void TreeKktSolver::SolveWithExtraRows(const VecX& rhs, const VecX& e, const MatX& S_inverse,
                                       VecX& x, VecX& mu) const {
  SolveForward(rhs);
  // G K^-1 rhs = sum F_k^T z_k (the L D L^T form, as S).
  VecX& g = extra_g_;  // G K^-1 rhs - e
  g = -e;
  for (int k : extra_nodes_) g.noalias() += ExtraF(k).transpose().lazyProduct(Z(k));
  mu.resize(ne_);
  mu.noalias() = S_inverse.lazyProduct(g);
  for (int k : extra_nodes_) Z(k).noalias() -= ExtraZ(k).lazyProduct(mu);
  SolveBackward(x);
}

const MatX& TreeKktSolver::ExtraRowResponses() const {
  if (extra_Y_current_) return extra_Y_;
  // The backward sweep on Z (zero off the extra rows' nodes): Y_k = Z_k - W_k Y_parent.
  extra_Y_blocks_.resize(nodes_.size());
  extra_Y_.setZero(size_, ne_);
  for (size_t k = 0; k < nodes_.size(); ++k) {
    const Node& node = nodes_[k];
    MatX& Y = extra_Y_blocks_[k];
    Y = ExtraZ(static_cast<int>(k));  // zero off the extra rows' nodes
    if (node.parent >= 0)
      Y.noalias() -= W(static_cast<int>(k)).lazyProduct(extra_Y_blocks_[node.parent].topRows<6>());
    const std::span<const int> global = Global(static_cast<int>(k));
    for (size_t i = 0; i < global.size(); ++i) extra_Y_.row(global[i]) = Y.row(i);
  }
  extra_Y_current_ = true;
  return extra_Y_;
}

}  // namespace sinew::engine

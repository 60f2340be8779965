#include <sinew/common/error.h>
#include <sinew/engine/kkt.h>
#include <sinew/math/finite.h>

#include <cmath>
#include <limits>
#include <string>

namespace sinew::engine {
namespace {
// Pivots of the Schur complement below this fraction of the largest are treated as zero
// (redundant constraints).
constexpr double kSchurThreshold = 1e-10;

// True when constraint k belongs to the tree elimination: the equations of a joint that places
// a body, or a constraint on the coordinates of one such joint and nothing else.
bool IsTreeConstraint(const System& system, int k) {
  const int num_joints = static_cast<int>(system.joints().size());
  if (k < num_joints) return !system.IsLoop(k);
  const Constraint& c = *system.constraints()[k];
  const std::vector<int> coordinates = c.Coordinates();
  if (!c.Bodies().empty() || coordinates.empty()) return false;
  const int joint = system.coordinates()[coordinates[0]].joint;
  for (int q : coordinates) {
    if (system.coordinates()[q].joint != joint) return false;
  }
  return !system.IsLoop(joint);
}
}  // namespace

Eigen::Matrix<double, 6, 6> CalcBodyMassMatrix(const Body& body, const Quat& quat_GB) {
  const Mat3 R = quat_GB.normalized().toRotationMatrix();
  const Vec3 c = R * body.p_BCm;
  const Mat3 I_G = R * body.I_Bcm_B * R.transpose();
  const Mat3 cx = Skew(c);
  const double m = body.mass;
  Eigen::Matrix<double, 6, 6> M;
  // -[c]x [c]x = |c|^2 I - c c^T (the parallel-axis term, without a 3 x 3 product).
  M.block<3, 3>(0, 0) = I_G - m * (c * c.transpose());
  M.block<3, 3>(0, 0).diagonal().array() += m * c.squaredNorm();
  M.block<3, 3>(0, 3) = m * cx;
  M.block<3, 3>(3, 0) = -m * cx;
  M.block<3, 3>(3, 3) = m * Mat3::Identity();
  return M;
}

KktSolver::KktSolver(const System& system, Method method) : system_(system), method_(method) {
  if (!system.finalized()) throw Error("engine: the System must be finalized before use");
  nv_ = 6 * (system.num_bodies() - 1) + system.num_integrated();
  const auto& constraints = system.constraints();
  nc_ = 0;
  for (const auto& c : constraints) {
    row_.push_back(nc_);
    nc_ += c->NumEquations();
    std::vector<int> cols;
    for (int b : c->Bodies()) {
      for (int i = 0; i < 6; ++i) cols.push_back(b == 0 ? -1 : BodyColumn(b) + i);
    }
    for (int q : c->Coordinates()) {
      if (!system.IsIntegrated(q)) {
        throw Error("engine: a constraint uses the speed of coordinate '" +
                    system.coordinates()[q].name + "' of a direct Cartesian joint");
      }
      cols.push_back(SpeedColumn(q));
    }
    jacobian_.push_back(MatX::Zero(c->NumEquations(), static_cast<int>(cols.size())));
    columns_.push_back(std::move(cols));
  }
  mass_.assign(system.num_bodies(), Eigen::Matrix<double, 6, 6>::Zero());
  tree_row_.assign(constraints.size(), -1);
  extra_row_.assign(constraints.size(), -1);
  for (size_t k = 0; k < constraints.size(); ++k) {
    const int n = constraints[k]->NumEquations();
    if (IsTreeConstraint(system, static_cast<int>(k))) {
      tree_constraints_.push_back(static_cast<int>(k));
      tree_row_[k] = nc_tree_;
      nc_tree_ += n;
    } else {
      extra_constraints_.push_back(static_cast<int>(k));
      extra_row_[k] = ne_;
      ne_ += n;
    }
  }
  if (method_ != Method::kDense) {
    std::vector<int> body_columns(system.num_bodies()), speed_columns(system.num_coordinates(), -1);
    for (int b = 0; b < system.num_bodies(); ++b) body_columns[b] = BodyColumn(b);
    for (int c = 0; c < system.num_coordinates(); ++c) {
      if (system.IsIntegrated(c)) speed_columns[c] = SpeedColumn(c);
    }
    tree_ =
        std::make_unique<TreeKktSolver>(system, nv_, body_columns, speed_columns, tree_constraints_,
                                        tree_row_, columns_, method_ == Method::kTree);
    G_ = MatX::Zero(ne_, nv_);
    S_ = MatX::Zero(ne_, ne_);
    if (ne_ > 0) {
      std::vector<int> extra_columns;
      for (int k : extra_constraints_) {
        for (int g : columns_[k]) {
          if (g >= 0) extra_columns.push_back(g);
        }
      }
      tree_->SetExtraRowColumns(ne_, extra_columns);
    }
  }
}

void KktSolver::GatherPositions(const State& state, VecX& out) const {
  out.resize(7 * (system_.num_bodies() - 1) + system_.num_integrated());
  int i = 0;
  for (int b = 1; b < system_.num_bodies(); ++b, i += 7) {
    out.segment<3>(i) = state.bodies[b].p_GB;
    out.segment<4>(i + 3) = state.bodies[b].quat_GB.coeffs();
  }
  for (int c = 0; c < system_.num_coordinates(); ++c) {
    if (system_.IsIntegrated(c)) out[i++] = state.q[c];
  }
}

bool KktSolver::IsFactorizedAt(const State& state) const {
  if (!factorized_) return false;
  GatherPositions(state, positions_);
  return positions_ == factorized_positions_;
}

void KktSolver::Factorize(const State& state) {
  factorized_ = false;  // until this factorization succeeds
  ++num_factorizations_;
  FactorizeMatrices(state);
  GatherPositions(state, factorized_positions_);
  factorized_ = true;
}

void KktSolver::FactorizeMatrices(const State& state) {
  const auto& constraints = system_.constraints();
  for (int b = 1; b < system_.num_bodies(); ++b) {
    mass_[b] = CalcBodyMassMatrix(system_.bodies()[b], state.bodies[b].quat_GB);
  }
  for (size_t k = 0; k < constraints.size(); ++k) {
    constraints[k]->CalcJacobian(system_, state, jacobian_[k]);
  }
  if (method_ == Method::kDense) {
    dense_.compute(AssembleDense());
    residual_check_ = true;
    return;
  }
  residual_check_ = false;
  if (ne_ == 0) {
    tree_->Factorize(mass_, jacobian_);
    return;
  }
  // The extra rows G over the velocity unknowns, then the tree and S = G K_T^-1 G^T together.
  G_.setZero();
  for (int k : extra_constraints_) {
    const MatX& J = jacobian_[k];
    for (int j = 0; j < J.cols(); ++j) {
      if (columns_[k][j] >= 0) G_.block(extra_row_[k], columns_[k][j], J.rows(), 1) += J.col(j);
    }
  }
  tree_->Factorize(mass_, jacobian_, G_, S_);
  schur_.setThreshold(kSchurThreshold);
  schur_.compute(S_);
  // Redundant extra constraints: the multipliers are least-squares ones, exact only when the
  // right-hand side is consistent; the residual tells. A full-rank S is inverted through an LU
  // whose buffers are reused (the pseudo-inverse allocates).
  residual_check_ = schur_.rank() < ne_;
  if (residual_check_) {
    schur_inverse_ = schur_.pseudoInverse();
  } else {
    // S^-1 = U^-1 L^-1 P, from the permutation matrix P (P S = L U) by two solves in place.
    schur_lu_.compute(S_);
    schur_inverse_.setZero(ne_, ne_);
    const auto& p = schur_lu_.permutationP().indices();
    for (int i = 0; i < ne_; ++i) schur_inverse_(p[i], i) = 1.0;
    schur_lu_.matrixLU().triangularView<Eigen::UnitLower>().solveInPlace(schur_inverse_);
    schur_lu_.matrixLU().triangularView<Eigen::Upper>().solveInPlace(schur_inverse_);
  }
}

void KktSolver::GatherTreeRhs(const VecX& rhs, VecX& tree_rhs) const {
  tree_rhs.resize(nv_ + nc_tree_);
  tree_rhs.head(nv_) = rhs.head(nv_);
  const auto& constraints = system_.constraints();
  for (int k : tree_constraints_) {
    const int n = constraints[k]->NumEquations();
    tree_rhs.segment(nv_ + tree_row_[k], n) = rhs.segment(nv_ + row_[k], n);
  }
}

VecX KktSolver::Solve(const VecX& rhs) const {
  VecX x;
  Solve(rhs, x);
  return x;
}

void KktSolver::Solve(const VecX& rhs, VecX& x) const {
  x.resize(nv_ + nc_);
  if (method_ == Method::kDense) {
    x = dense_.solve(rhs);
    CheckSolution(rhs, x);
    return;
  }
  if (ne_ == 0) {
    // Every constraint is a tree constraint, numbered in the same order: the tree solver's
    // vectors are the KKT ones.
    tree_->Solve(rhs, x);
    CheckSolution(rhs, x);
    return;
  }
  GatherTreeRhs(rhs, tree_rhs_);
  const auto& constraints = system_.constraints();
  // The extra constraints (ne_ > 0 here): the Schur complement on their rows, inside the tree
  // solve.
  g_.resize(ne_);
  for (int k : extra_constraints_) {
    const int n = constraints[k]->NumEquations();
    g_.segment(extra_row_[k], n) = rhs.segment(nv_ + row_[k], n);
  }
  tree_->SolveWithExtraRows(tree_rhs_, g_, schur_inverse_, y_, mu_);
  for (int k : extra_constraints_) {
    const int n = constraints[k]->NumEquations();
    x.segment(nv_ + row_[k], n) = mu_.segment(extra_row_[k], n);
  }
  x.head(nv_) = y_.head(nv_);
  for (int k : tree_constraints_) {
    const int n = constraints[k]->NumEquations();
    x.segment(nv_ + row_[k], n) = y_.segment(nv_ + tree_row_[k], n);
  }
  CheckSolution(rhs, x);
}

bool KktSolver::SolveUnitLoadResponses(int source, const std::vector<int>& targets,
                                       Eigen::Ref<MatX> out) const {
  if (!tree_) return false;
  tree_->SolveUnitLoadResponses(source, targets, out);
  if (ne_ == 0) return true;
  // The Schur complement's correction x -= Y mu with mu = S^-1 (G y0), where G y0 for the unit
  // loads is Y_s^T (the source's rows of Y): out_t -= Y_t S^-1 Y_s^T.
  const MatX& Y = tree_->ExtraRowResponses();
  unit_mu_.resize(ne_, 6);
  unit_mu_.noalias() = schur_inverse_ * Y.middleRows<6>(BodyColumn(source)).transpose();
  for (size_t t = 0; t < targets.size(); ++t) {
    out.block<6, 6>(6 * static_cast<Eigen::Index>(t), 0).noalias() -=
        Y.middleRows<6>(BodyColumn(targets[t])) * unit_mu_;
  }
  return true;
}

void KktSolver::CheckSolution(const VecX& rhs, const VecX& x) const {
  // The tree elimination is exact once every pivot block passed its conditioning test in
  // Factorize, and so is a full-rank Schur complement: their solutions need no residual (an
  // O(n) pass as long as the solve itself). A pseudo-inverse of a rank-deficient Schur
  // complement and the dense LU are checked.
  if (!residual_check_) {
    if (!AllFinite(x)) ThrowSingular(std::numeric_limits<double>::quiet_NaN());
    return;
  }
  // [M x_v + J^T lambda - f; J x_v - g], accumulated in place.
  residual_.resize(nv_ + nc_);
  residual_ = -rhs;
  for (int b = 1; b < system_.num_bodies(); ++b) {
    residual_.segment<6>(BodyColumn(b)).noalias() += mass_[b] * x.segment<6>(BodyColumn(b));
  }
  for (size_t k = 0; k < jacobian_.size(); ++k) {
    const MatX& J = jacobian_[k];
    for (int j = 0; j < J.cols(); ++j) {
      const int col = columns_[k][j];
      if (col < 0) continue;
      for (int i = 0; i < J.rows(); ++i) {
        residual_[col] += J(i, j) * x[nv_ + row_[k] + i];
        residual_[nv_ + row_[k] + i] += J(i, j) * x[col];
      }
    }
  }
  const double scale = 1.0 + rhs.lpNorm<Eigen::Infinity>();
  if (!x.allFinite() || residual_.lpNorm<Eigen::Infinity>() > 1e-6 * scale) {
    ThrowSingular(residual_.lpNorm<Eigen::Infinity>());
  }
}

void KktSolver::ThrowSingular(double residual) const {
  throw Error("engine: the equations of motion are singular or ill-conditioned (residual " +
              std::to_string(residual) + "); check for bodies without mass or inertia");
}

VecX KktSolver::MultiplyMass(const VecX& x) const {
  VecX y;
  MultiplyMass(x, y);
  return y;
}

void KktSolver::MultiplyMass(const VecX& x, VecX& y) const {
  y.setZero(nv_);
  for (int b = 1; b < system_.num_bodies(); ++b) {
    y.segment<6>(BodyColumn(b)) = mass_[b] * x.segment<6>(BodyColumn(b));
  }
}

VecX KktSolver::MultiplyJacobian(const VecX& x) const {
  VecX y = VecX::Zero(nc_);
  for (size_t k = 0; k < jacobian_.size(); ++k) {
    const MatX& J = jacobian_[k];
    for (int j = 0; j < J.cols(); ++j) {
      if (columns_[k][j] >= 0) y.segment(row_[k], J.rows()) += J.col(j) * x[columns_[k][j]];
    }
  }
  return y;
}

MatX KktSolver::AssembleDense() const {
  std::vector<Eigen::Triplet<double>> entries;
  AppendTriplets(entries);
  MatX K = MatX::Zero(nv_ + nc_, nv_ + nc_);
  for (const Eigen::Triplet<double>& e : entries) K(e.row(), e.col()) += e.value();
  return K;
}

void KktSolver::AppendTriplets(std::vector<Eigen::Triplet<double>>& out) const {
  for (int b = 1; b < system_.num_bodies(); ++b) {
    const int col = BodyColumn(b);
    for (int j = 0; j < 6; ++j) {
      for (int i = 0; i < 6; ++i) {
        if (mass_[b](i, j) != 0.0) out.emplace_back(col + i, col + j, mass_[b](i, j));
      }
    }
  }
  for (size_t k = 0; k < jacobian_.size(); ++k) {
    const MatX& J = jacobian_[k];
    for (int i = 0; i < J.rows(); ++i) {
      for (int j = 0; j < J.cols(); ++j) {
        if (columns_[k][j] < 0) continue;
        out.emplace_back(nv_ + row_[k] + i, columns_[k][j], J(i, j));
        out.emplace_back(columns_[k][j], nv_ + row_[k] + i, J(i, j));
      }
    }
  }
}

VecX KktSolver::MultiplyJacobianTranspose(const VecX& y) const {
  VecX x = VecX::Zero(nv_);
  for (size_t k = 0; k < jacobian_.size(); ++k) {
    const MatX& J = jacobian_[k];
    for (int j = 0; j < J.cols(); ++j) {
      if (columns_[k][j] >= 0) x[columns_[k][j]] += J.col(j).dot(y.segment(row_[k], J.rows()));
    }
  }
  return x;
}

VecX GatherVelocities(const System& system, const KktSolver& kkt, const State& state) {
  VecX v(kkt.num_velocities());
  GatherVelocities(system, kkt, state, v);
  return v;
}

void GatherVelocities(const System& system, const KktSolver& kkt, const State& state,
                      Eigen::Ref<VecX> v) {
  for (int b = 1; b < system.num_bodies(); ++b) {
    v.segment<3>(kkt.BodyColumn(b)) = state.bodies[b].w_GB;
    v.segment<3>(kkt.BodyColumn(b) + 3) = state.bodies[b].v_GB;
  }
  for (int c = 0; c < system.num_coordinates(); ++c) {
    if (system.IsIntegrated(c)) v[kkt.SpeedColumn(c)] = state.u[c];
  }
}

void ScatterVelocities(const System& system, const KktSolver& kkt, Eigen::Ref<const VecX> v,
                       State& state) {
  for (int b = 1; b < system.num_bodies(); ++b) {
    state.bodies[b].w_GB = v.segment<3>(kkt.BodyColumn(b));
    state.bodies[b].v_GB = v.segment<3>(kkt.BodyColumn(b) + 3);
  }
  for (int c = 0; c < system.num_coordinates(); ++c) {
    if (system.IsIntegrated(c)) state.u[c] = v[kkt.SpeedColumn(c)];
  }
}

}  // namespace sinew::engine

#include <sinew/common/error.h>
#include <sinew/engine/kkt.h>

#include <cmath>
#include <string>

namespace sinew::engine {
namespace {
// Constraint compliance of the sparse path (see Factorize).
constexpr double kCompliance = 1e-12;
}  // namespace

Eigen::Matrix<double, 6, 6> CalcBodyMassMatrix(const Body& body, const Quat& quat_GB) {
  const Mat3 R = quat_GB.normalized().toRotationMatrix();
  const Vec3 c = R * body.p_BCm;
  const Mat3 I_G = R * body.I_Bcm_B * R.transpose();
  const Mat3 cx = Skew(c);
  const double m = body.mass;
  Eigen::Matrix<double, 6, 6> M;
  M.block<3, 3>(0, 0) = I_G - m * cx * cx;
  M.block<3, 3>(0, 3) = m * cx;
  M.block<3, 3>(3, 0) = -m * cx;
  M.block<3, 3>(3, 3) = m * Mat3::Identity();
  return M;
}

KktSolver::KktSolver(const System& system, bool allow_tree) : system_(system) {
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
  matrix_.resize(nv_ + nc_, nv_ + nc_);
  // Without loop constraints the tree elimination applies: constraints are the joints', then
  // coordinate constraints that touch one coordinate's speed only.
  bool tree = allow_tree && !system.HasLoops();
  for (size_t k = system.joints().size(); k < constraints.size() && tree; ++k) {
    const std::vector<int> coordinates = constraints[k]->Coordinates();
    tree = constraints[k]->Bodies().empty() && !coordinates.empty();
    for (int c : coordinates) {
      tree = tree && system.coordinates()[c].joint == system.coordinates()[coordinates[0]].joint;
    }
  }
  if (tree) {
    std::vector<int> body_columns(system.num_bodies()), speed_columns(system.num_coordinates(), -1);
    for (int b = 0; b < system.num_bodies(); ++b) body_columns[b] = BodyColumn(b);
    for (int c = 0; c < system.num_coordinates(); ++c) {
      if (system.IsIntegrated(c)) speed_columns[c] = SpeedColumn(c);
    }
    try {
      tree_ =
          std::make_unique<TreeKktSolver>(system, nv_, body_columns, speed_columns, row_, columns_);
    } catch (const Error&) {
      tree_.reset();  // a structure the tree solver does not take: the sparse LU does
    }
  }
}

void KktSolver::Factorize(const State& state) {
  const auto& constraints = system_.constraints();
  triplets_.clear();
  for (int b = 1; b < system_.num_bodies(); ++b) {
    mass_[b] = CalcBodyMassMatrix(system_.bodies()[b], state.bodies[b].quat_GB);
    const int c0 = BodyColumn(b);
    for (int i = 0; i < 6; ++i) {
      for (int k = 0; k < 6; ++k) triplets_.emplace_back(c0 + i, c0 + k, mass_[b](i, k));
    }
  }
  for (size_t k = 0; k < constraints.size(); ++k) {
    constraints[k]->CalcJacobian(system_, state, jacobian_[k]);
  }
  if (tree_) {
    tree_->Factorize(mass_, jacobian_);
    return;
  }
  for (size_t k = 0; k < constraints.size(); ++k) {
    const MatX& J = jacobian_[k];
    const auto& cols = columns_[k];
    for (int i = 0; i < J.rows(); ++i) {
      const int row = nv_ + row_[k] + i;
      for (int j = 0; j < J.cols(); ++j) {
        if (cols[j] < 0) continue;
        triplets_.emplace_back(row, cols[j], J(i, j));
        triplets_.emplace_back(cols[j], row, J(i, j));
      }
    }
  }
  // A tiny compliance -eps on the constraint diagonal keeps redundant (consistent) loop
  // constraints solvable, as with planar loops of pins; it changes J x = g by eps * lambda.
  for (int r = 0; r < nc_; ++r) triplets_.emplace_back(nv_ + r, nv_ + r, -kCompliance);
  matrix_.setFromTriplets(triplets_.begin(), triplets_.end());
  if (!analyzed_) {
    lu_.analyzePattern(matrix_);
    analyzed_ = true;
  }
  lu_.factorize(matrix_);
  if (lu_.info() != Eigen::Success) {
    throw Error(
        "engine: the equations of motion are singular (bodies without mass or inertia in "
        "a direction no joint constrains?): " +
        lu_.lastErrorMessage());
  }
}

VecX KktSolver::Solve(const VecX& rhs) const {
  VecX x = tree_ ? tree_->Solve(rhs) : VecX(lu_.solve(rhs));
  VecX residual(rhs.size());
  residual.head(nv_) =
      MultiplyMass(x.head(nv_)) + MultiplyJacobianTranspose(x.tail(nc_)) - rhs.head(nv_);
  residual.tail(nc_) = MultiplyJacobian(x.head(nv_)) - rhs.tail(nc_);
  if (!tree_) residual.tail(nc_) -= kCompliance * x.tail(nc_);
  const double scale = 1.0 + rhs.lpNorm<Eigen::Infinity>();
  if (!x.allFinite() || residual.lpNorm<Eigen::Infinity>() > 1e-6 * scale) {
    throw Error("engine: the equations of motion are singular or ill-conditioned (residual " +
                std::to_string(residual.lpNorm<Eigen::Infinity>()) +
                "); check for bodies without mass or inertia");
  }
  return x;
}

VecX KktSolver::MultiplyMass(const VecX& x) const {
  VecX y = VecX::Zero(nv_);
  for (int b = 1; b < system_.num_bodies(); ++b) {
    y.segment<6>(BodyColumn(b)) = mass_[b] * x.segment<6>(BodyColumn(b));
  }
  return y;
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
  MatX K = MatX::Zero(nv_ + nc_, nv_ + nc_);
  for (int b = 1; b < system_.num_bodies(); ++b) {
    K.block<6, 6>(BodyColumn(b), BodyColumn(b)) = mass_[b];
  }
  for (size_t k = 0; k < jacobian_.size(); ++k) {
    const MatX& J = jacobian_[k];
    for (int i = 0; i < J.rows(); ++i) {
      for (int j = 0; j < J.cols(); ++j) {
        if (columns_[k][j] < 0) continue;
        K(nv_ + row_[k] + i, columns_[k][j]) += J(i, j);
        K(columns_[k][j], nv_ + row_[k] + i) += J(i, j);
      }
    }
  }
  if (!tree_) K.bottomRightCorner(nc_, nc_).diagonal().array() -= kCompliance;
  return K;
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
  for (int b = 1; b < system.num_bodies(); ++b) {
    v.segment<3>(kkt.BodyColumn(b)) = state.bodies[b].w_GB;
    v.segment<3>(kkt.BodyColumn(b) + 3) = state.bodies[b].v_GB;
  }
  for (int c = 0; c < system.num_coordinates(); ++c) {
    if (system.IsIntegrated(c)) v[kkt.SpeedColumn(c)] = state.u[c];
  }
  return v;
}

void ScatterVelocities(const System& system, const KktSolver& kkt, const VecX& v, State& state) {
  for (int b = 1; b < system.num_bodies(); ++b) {
    state.bodies[b].w_GB = v.segment<3>(kkt.BodyColumn(b));
    state.bodies[b].v_GB = v.segment<3>(kkt.BodyColumn(b) + 3);
  }
  for (int c = 0; c < system.num_coordinates(); ++c) {
    if (system.IsIntegrated(c)) state.u[c] = v[kkt.SpeedColumn(c)];
  }
}

}  // namespace sinew::engine

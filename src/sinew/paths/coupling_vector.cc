#include <sinew/paths/coupling_vector.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>

namespace sinew::paths {
namespace {

// The velocity constraints A u = 0 at q: every enforced coupler, and u_c = 0 for every locked
// coordinate c but `free_coordinate` (-1: none).
Eigen::MatrixXd ConstraintRows(const model::ModelSpec& spec,
                               const kinematics::CoordinateCouplers& couplers,
                               std::span<const double> q, int free_coordinate) {
  const size_t n = q.size();
  std::vector<std::vector<double>> rows;
  couplers.AppendVelocityRows(q, rows);
  for (size_t c = 0; c < spec.coordinates.size(); ++c) {
    if (spec.coordinates[c].locked && static_cast<int>(c) != free_coordinate) {
      std::vector<double> row(n, 0.0);
      row[c] = 1.0;
      rows.push_back(std::move(row));
    }
  }
  Eigen::MatrixXd A(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(n));
  for (size_t r = 0; r < rows.size(); ++r) {
    for (size_t c = 0; c < n; ++c) {
      A(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = rows[r][c];
    }
  }
  return A;
}

// The coupling vector from u = e_j - A^T lambda, with lambda = (A A^T)^+ A e_j: u / u_j, or all
// NaN when u_j vanishes. Into `coupling` (resized to A's columns).
void CouplingFrom(const Eigen::MatrixXd& A, const Eigen::VectorXd& lambda, int j,
                  std::vector<double>& coupling) {
  Eigen::VectorXd u = -A.transpose() * lambda;
  u(j) += 1.0;
  const double u_j = u(j);
  const size_t n = static_cast<size_t>(A.cols());
  if (!(std::abs(u_j) > 1e-12)) {
    coupling.assign(n, std::numeric_limits<double>::quiet_NaN());
    return;
  }
  coupling.resize(n);
  for (size_t c = 0; c < n; ++c) coupling[c] = u(static_cast<Eigen::Index>(c)) / u_j;
}

// The one row of A that involves coordinate j when that row shares no coordinate with any other
// row (a coupler whose coordinates no other coupler or lock involves: each of Rajagopal's knees
// with its patella); -1 otherwise. A A^T is then block diagonal with (a_r . a_r) alone in its
// block, and A e_j is zero outside row r, so (A A^T)^+ A e_j is a_rj / (a_r . a_r) at r and zero
// elsewhere: no factorization.
Eigen::Index LoneRow(const Eigen::MatrixXd& A, int j) {
  Eigen::Index r = -1;
  for (Eigen::Index i = 0; i < A.rows(); ++i) {
    if (A(i, j) == 0.0) continue;
    if (r >= 0) return -1;
    r = i;
  }
  if (r < 0) return -1;
  for (Eigen::Index c = 0; c < A.cols(); ++c) {
    if (A(r, c) == 0.0) continue;
    for (Eigen::Index i = 0; i < A.rows(); ++i) {
      if (i != r && A(i, c) != 0.0) return -1;
    }
  }
  return r;
}

// e_j of size n, into `e`.
void Unit(size_t n, int j, std::vector<double>& e) {
  e.assign(n, 0.0);
  e[static_cast<size_t>(j)] = 1.0;
}

}  // namespace

std::vector<double> CalcCouplingVector(const model::ModelSpec& spec,
                                       const kinematics::CoordinateCouplers& couplers,
                                       std::span<const double> q, int j) {
  std::vector<double> coupling;
  const Eigen::MatrixXd A = ConstraintRows(spec, couplers, q, j);
  if (A.rows() == 0) {
    Unit(q.size(), j, coupling);
    return coupling;
  }
  // u = e_j - A^T (A A^T)^+ A e_j: the nearest speeds to e_j that satisfy A u = 0.
  const Eigen::MatrixXd AAt = A * A.transpose();
  const Eigen::VectorXd Ae_j = A.col(j);
  CouplingFrom(A, AAt.completeOrthogonalDecomposition().solve(Ae_j), j, coupling);
  return coupling;
}

void CalcCouplingVectors(const model::ModelSpec& spec,
                         const kinematics::CoordinateCouplers& couplers, std::span<const double> q,
                         std::span<const int> coordinates, std::vector<std::vector<double>>& out) {
  out.resize(coordinates.size());
  const Eigen::MatrixXd A = ConstraintRows(spec, couplers, q, -1);
  // The rows are factorized once, when a coordinate first needs them.
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> AAt;
  bool factorized = false;
  for (size_t k = 0; k < coordinates.size(); ++k) {
    const int j = coordinates[k];
    if (spec.coordinates[static_cast<size_t>(j)].locked) {
      out[k] = CalcCouplingVector(spec, couplers, q, j);  // its own rows: j is free to move
    } else if ((A.col(j).array() == 0.0).all()) {
      // No constraint involves j (A e_j = 0, so lambda = 0): it moves alone. Most coordinates.
      Unit(q.size(), j, out[k]);
    } else if (const Eigen::Index r = LoneRow(A, j); r >= 0) {
      Eigen::VectorXd lambda = Eigen::VectorXd::Zero(A.rows());
      lambda(r) = A(r, j) / A.row(r).squaredNorm();
      CouplingFrom(A, lambda, j, out[k]);
    } else {
      if (!factorized) {
        AAt.compute(A * A.transpose());
        factorized = true;
      }
      const Eigen::VectorXd Ae_j = A.col(j);
      CouplingFrom(A, AAt.solve(Ae_j), j, out[k]);
    }
  }
}

}  // namespace sinew::paths

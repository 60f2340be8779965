#include <sinew/paths/coupling_vector.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>

namespace sinew::paths {

std::vector<double> CalcCouplingVector(const model::ModelSpec& spec,
                                       const kinematics::CoordinateCouplers& couplers,
                                       std::span<const double> q, int j) {
  const size_t n = q.size();
  std::vector<std::vector<double>> rows;
  couplers.AppendVelocityRows(q, rows);
  for (size_t c = 0; c < spec.coordinates.size(); ++c) {
    if (spec.coordinates[c].locked && static_cast<int>(c) != j) {
      std::vector<double> row(n, 0.0);
      row[c] = 1.0;
      rows.push_back(std::move(row));
    }
  }
  std::vector<double> coupling(n, 0.0);
  coupling[static_cast<size_t>(j)] = 1.0;
  if (rows.empty()) return coupling;
  // u = e_j - A^T (A A^T)^+ A e_j: the nearest speeds to e_j that satisfy A u = 0.
  Eigen::MatrixXd A(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(n));
  for (size_t r = 0; r < rows.size(); ++r) {
    for (size_t c = 0; c < n; ++c)
      A(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = rows[r][c];
  }
  const Eigen::VectorXd Ae_j = A.col(j);
  const Eigen::MatrixXd AAt = A * A.transpose();
  const Eigen::VectorXd lambda = AAt.completeOrthogonalDecomposition().solve(Ae_j);
  Eigen::VectorXd u = -A.transpose() * lambda;
  u(j) += 1.0;
  const double u_j = u(j);
  if (!(std::abs(u_j) > 1e-12)) {
    return std::vector<double>(n, std::numeric_limits<double>::quiet_NaN());
  }
  for (size_t c = 0; c < n; ++c) coupling[c] = u(static_cast<Eigen::Index>(c)) / u_j;
  return coupling;
}

}  // namespace sinew::paths

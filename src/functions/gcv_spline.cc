#include "functions/gcv_spline.h"

#include <cmath>

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#include "common/error.h"
#include "functions/derivative_order.h"
#include "functions/knots.h"

namespace sinew {
namespace {

// j (j-1) ... (j-r+1): the factor d^r/du^r u^j = FallingFactorial(j, r) u^(j-r).
double FallingFactorial(int j, int r) {
  double f = 1.0;
  for (int i = 0; i < r; ++i) f *= j - i;
  return f;
}

}  // namespace

GCVSpline::GCVSpline(int half_order, std::vector<double> x, std::vector<double> y,
                     double error_variance)
    : half_order_(half_order), x_(std::move(x)), y_(std::move(y)) {
  if (half_order_ < 1 || half_order_ > 4) {
    throw Error("GCVSpline: half_order must be 1..4, got " + std::to_string(half_order_));
  }
  if (error_variance != 0.0) {
    throw Error(
        "GCVSpline: only error_variance 0 (interpolation) is supported; smoothing fits are not "
        "implemented");
  }
  const int m = half_order_;
  CheckKnots(x_, y_, 2 * m, "GCVSpline");
  for (size_t i = 1; i < x_.size(); ++i) {
    if (!(x_[i] > x_[i - 1])) throw Error("GCVSpline: x must be strictly increasing");
  }
  const int n = static_cast<int>(x_.size());
  const int width = 2 * m;  // coefficients per interval
  const int unknowns = (n - 1) * width;

  // One sparse row per condition; derivative rows are written in units of the left interval
  // (times h^r) to keep the system well scaled.
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(unknowns);
  int row = 0;
  auto h = [&](int k) { return x_[k + 1] - x_[k]; };
  // Adds `scale` * (d^r/du^r of piece k at u) to the current row.
  auto add_derivative = [&](int k, double u, int r, double scale) {
    double power = 1.0;  // u^(j - r)
    for (int j = r; j < width; ++j) {
      entries.emplace_back(row, k * width + j, scale * FallingFactorial(j, r) * power);
      power *= u;
    }
  };
  for (int k = 0; k + 1 < n; ++k) {
    // Interpolation at both ends of each interval.
    add_derivative(k, 0.0, 0, 1.0);
    rhs(row++) = y_[k];
    add_derivative(k, 1.0, 0, 1.0);
    rhs(row++) = y_[k + 1];
  }
  // Continuity of derivatives 1 .. 2m-2 at interior knots: piece i-1 at u = 1 equals piece i
  // at u = 0, after the chain rule 1/h^r (rows multiplied by h_{i-1}^r).
  for (int i = 1; i + 1 < n; ++i) {
    for (int r = 1; r <= 2 * m - 2; ++r) {
      add_derivative(i - 1, 1.0, r, 1.0);
      add_derivative(i, 0.0, r, -std::pow(h(i - 1) / h(i), r));
      ++row;
    }
  }
  // Natural end conditions: derivatives m .. 2m-2 vanish at both ends.
  for (int r = m; r <= 2 * m - 2; ++r) {
    add_derivative(0, 0.0, r, 1.0);
    ++row;
    add_derivative(n - 2, 1.0, r, 1.0);
    ++row;
  }
  if (row != unknowns) throw Error("GCVSpline: internal error, system is not square");

  Eigen::SparseMatrix<double> matrix(unknowns, unknowns);
  matrix.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> solver;
  solver.compute(matrix);
  if (solver.info() != Eigen::Success) throw Error("GCVSpline: the spline system is singular");
  Eigen::VectorXd solution = solver.solve(rhs);
  coefficients_.assign(solution.data(), solution.data() + unknowns);

  for (int r = 0; r < m; ++r) {
    start_derivatives_.push_back(CalcPiece(0, x_.front(), r));
    end_derivatives_.push_back(CalcPiece(n - 2, x_.back(), r));
  }
}

double GCVSpline::CalcPiece(int k, double x, int order) const {
  const int width = 2 * half_order_;
  const double h = x_[k + 1] - x_[k];
  const double u = (x - x_[k]) / h;
  const double* a = &coefficients_[k * width];
  // Horner on the differentiated coefficients.
  double sum = 0.0;
  for (int j = width - 1; j >= order; --j) sum = sum * u + FallingFactorial(j, order) * a[j];
  return sum / std::pow(h, order);
}

double GCVSpline::CalcDerivative(double x, int order) const {
  CheckDerivativeOrder(order, TypeName());
  const bool before = x < x_.front();
  if (before || x > x_.back()) {
    // The degree m-1 polynomial with the end derivatives: sum_r D^r (x - x_end)^(r - order) /
    // (r - order)!.
    const std::vector<double>& derivatives = before ? start_derivatives_ : end_derivatives_;
    const double dx = x - (before ? x_.front() : x_.back());
    double sum = 0.0;
    double term = 1.0;  // dx^(r - order) / (r - order)!
    for (int r = order; r < half_order_; ++r) {
      sum += derivatives[r] * term;
      term *= dx / (r - order + 1);
    }
    return sum;
  }
  return CalcPiece(FindKnotInterval(x_, x), x, order);
}

}  // namespace sinew

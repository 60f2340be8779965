#include <sinew/common/error.h>
#include <sinew/functions/derivative_order.h>
#include <sinew/functions/gcv_spline.h>
#include <sinew/functions/knots.h>

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <limits>

namespace sinew::functions {
namespace {

// j (j-1) ... (j-r+1): the factor d^r/du^r u^j = FallingFactorial(j, r) u^(j-r).
double FallingFactorial(int j, int r) {
  double f = 1.0;
  for (int i = 0; i < r; ++i) f *= j - i;
  return f;
}

// The linear system of the natural spline of degree 2m-1 on knots x that minimizes
//   sum_i (y_i - s(x_i))^2 + p * integral (s^(m))^2 dx
// (p = 0: the interpolating spline). Unknowns: per interval k the 2m coefficients of
// u^j, u = (x - x_k) / h_k. Rows: continuity of value and derivatives 1..2m-2 at interior
// knots, natural end conditions (derivatives m..2m-2 zero at both ends), and per knot the
// optimality condition s(x_i) + p (-1)^m J_i = y_i, with J_i the jump of s^(2m-1) at x_i
// (s^(2m-1) is 0 outside the knots). The last rows come from integrating the penalty's first
// variation by parts m times. Factorized once; solved for any data.
class NaturalSplineSystem {
 public:
  NaturalSplineSystem(const std::vector<double>& x, int m, double p)
      : x_(x), m_(m), n_(static_cast<int>(x.size())), width_(2 * m) {
    const int unknowns = (n_ - 1) * width_;
    std::vector<Eigen::Triplet<double>> entries;
    int row = 0;
    auto h = [&](int k) { return x_[k + 1] - x_[k]; };
    // Adds `scale` * (d^r/du^r of piece k at u) to the current row.
    auto add_derivative = [&](int k, double u, int r, double scale) {
      double power = 1.0;  // u^(j - r)
      for (int j = r; j < width_; ++j) {
        entries.emplace_back(row, k * width_ + j, scale * FallingFactorial(j, r) * power);
        power *= u;
      }
    };
    // Continuity of derivatives 0 .. 2m-2 at interior knots (rows scaled by h_{i-1}^r).
    for (int i = 1; i + 1 < n_; ++i) {
      for (int r = 0; r <= 2 * m_ - 2; ++r) {
        add_derivative(i - 1, 1.0, r, 1.0);
        add_derivative(i, 0.0, r, -std::pow(h(i - 1) / h(i), r));
        ++row;
      }
    }
    // Natural end conditions.
    for (int r = m_; r <= 2 * m_ - 2; ++r) {
      add_derivative(0, 0.0, r, 1.0);
      ++row;
      add_derivative(n_ - 2, 1.0, r, 1.0);
      ++row;
    }
    // Knot rows: s(x_i) + p (-1)^m (s^(2m-1)(x_i+) - s^(2m-1)(x_i-)) = y_i.
    const int top = 2 * m_ - 1;
    const double factor = (m_ % 2 == 0 ? 1.0 : -1.0) * p * FallingFactorial(top, top);
    for (int i = 0; i < n_; ++i) {
      data_rows_.push_back(row);
      if (i + 1 < n_) {
        add_derivative(i, 0.0, 0, 1.0);
      } else {
        add_derivative(n_ - 2, 1.0, 0, 1.0);
      }
      if (p != 0.0) {
        if (i + 1 < n_) entries.emplace_back(row, i * width_ + top, factor / std::pow(h(i), top));
        if (i > 0) {
          entries.emplace_back(row, (i - 1) * width_ + top, -factor / std::pow(h(i - 1), top));
        }
      }
      ++row;
    }
    if (row != unknowns) throw Error("GCVSpline: internal error, system is not square");
    Eigen::SparseMatrix<double> matrix(unknowns, unknowns);
    matrix.setFromTriplets(entries.begin(), entries.end());
    solver_.compute(matrix);
    if (solver_.info() != Eigen::Success) throw Error("GCVSpline: the spline system is singular");
  }

  // Spline coefficients for data y.
  Eigen::VectorXd Solve(const std::vector<double>& y) {
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero((n_ - 1) * width_);
    for (int i = 0; i < n_; ++i) rhs(data_rows_[i]) = y[i];
    return solver_.solve(rhs);
  }

  // s(x_i) for coefficients z.
  template <typename Vector>
  double KnotValue(const Vector& z, int i) const {
    if (i + 1 < n_) return z(i * width_);
    return z.segment((n_ - 2) * width_, width_).sum();
  }

  // Trace of the influence matrix A = d s(x_i) / d y_j: one solve per data point, done in
  // blocks of right-hand sides.
  double InfluenceTrace() {
    constexpr int kBlock = 32;
    const int unknowns = (n_ - 1) * width_;
    double trace = 0.0;
    for (int first = 0; first < n_; first += kBlock) {
      const int count = std::min(kBlock, n_ - first);
      Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(unknowns, count);
      for (int j = 0; j < count; ++j) rhs(data_rows_[first + j], j) = 1.0;
      const Eigen::MatrixXd z = solver_.solve(rhs);
      for (int j = 0; j < count; ++j) trace += KnotValue(z.col(j), first + j);
    }
    return trace;
  }

 private:
  std::vector<double> x_;
  int m_, n_, width_;
  std::vector<int> data_rows_;
  Eigen::SparseLU<Eigen::SparseMatrix<double>> solver_;
};

// Natural scale of p: p0 * (2m-1)! / h^(2m-1) = 1 for the mean spacing h.
double SmoothingScale(const std::vector<double>& x, int m) {
  const double mean_spacing = (x.back() - x.front()) / static_cast<double>(x.size() - 1);
  return std::pow(mean_spacing, 2 * m - 1) / FallingFactorial(2 * m - 1, 2 * m - 1);
}

}  // namespace

double GCVSpline::CalcSmoothingCriterion(int half_order, const std::vector<double>& x,
                                         const std::vector<double>& y, double error_variance,
                                         double p) {
  NaturalSplineSystem system(x, half_order, p);
  const Eigen::VectorXd z = system.Solve(y);
  const double n = static_cast<double>(x.size());
  double residual = 0.0;
  for (size_t i = 0; i < x.size(); ++i) {
    const double r = y[i] - system.KnotValue(z, static_cast<int>(i));
    residual += r * r;
  }
  const double mean_residual = residual / n;
  const double trace_fraction = 1.0 - system.InfluenceTrace() / n;  // tr(I - A) / n
  if (error_variance < 0.0) return mean_residual / (trace_fraction * trace_fraction);  // GCV
  return mean_residual - error_variance * (2.0 * trace_fraction - 1.0);
}

GCVSpline::GCVSpline(int half_order, std::vector<double> x, std::vector<double> y,
                     double error_variance)
    : half_order_(half_order), x_(std::move(x)), y_(std::move(y)) {
  CheckInput();
  if (error_variance != 0.0) {
    smoothing_parameter_ = ChooseSmoothingParameter(error_variance);
  }
  Fit();
}

GCVSpline GCVSpline::WithSmoothingParameter(int half_order, std::vector<double> x,
                                            std::vector<double> y, double p) {
  if (!(p >= 0.0) || !std::isfinite(p)) {
    throw Error("GCVSpline: the smoothing parameter must be finite and >= 0");
  }
  return GCVSpline(half_order, std::move(x), std::move(y), p, FixedSmoothing{});
}

GCVSpline::GCVSpline(int half_order, std::vector<double> x, std::vector<double> y, double p,
                     FixedSmoothing)
    : half_order_(half_order), x_(std::move(x)), y_(std::move(y)), smoothing_parameter_(p) {
  CheckInput();
  Fit();
}

void GCVSpline::CheckInput() const {
  if (half_order_ < 1 || half_order_ > 4) {
    throw Error("GCVSpline: half_order must be 1..4, got " + std::to_string(half_order_));
  }
  CheckKnots(x_, y_, 2 * half_order_, "GCVSpline");
  for (size_t i = 1; i < x_.size(); ++i) {
    if (!(x_[i] > x_[i - 1])) throw Error("GCVSpline: x must be strictly increasing");
  }
}

// Minimizes the criterion over log10(p / p0) in [-12, 12]: a grid of half decades, then golden
// section around the best grid point down to 1e-9 decades. The best grid point at the lower end
// means interpolation is best (p = 0).
double GCVSpline::ChooseSmoothingParameter(double error_variance) const {
  const double p0 = SmoothingScale(x_, half_order_);
  auto criterion = [&](double t) {
    return CalcSmoothingCriterion(half_order_, x_, y_, error_variance, p0 * std::pow(10.0, t));
  };
  constexpr double kLow = -12.0, kHigh = 12.0, kStep = 0.5;
  double best_t = kLow;
  double best = std::numeric_limits<double>::infinity();
  for (double t = kLow; t <= kHigh + 1e-9; t += kStep) {
    const double value = criterion(t);
    if (value < best) {
      best = value;
      best_t = t;
    }
  }
  if (best_t <= kLow) return 0.0;
  double a = best_t - kStep, b = std::min(kHigh, best_t + kStep);
  const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
  double c = b - ratio * (b - a), d = a + ratio * (b - a);
  double fc = criterion(c), fd = criterion(d);
  while (b - a > 1e-9) {
    if (fc <= fd) {
      b = d;
      d = c;
      fd = fc;
      c = b - ratio * (b - a);
      fc = criterion(c);
    } else {
      a = c;
      c = d;
      fc = fd;
      d = a + ratio * (b - a);
      fd = criterion(d);
    }
  }
  return p0 * std::pow(10.0, 0.5 * (a + b));
}

void GCVSpline::Fit() {
  const int m = half_order_;
  const int n = static_cast<int>(x_.size());
  NaturalSplineSystem system(x_, m, smoothing_parameter_);
  const Eigen::VectorXd solution = system.Solve(y_);
  coefficients_.assign(solution.data(), solution.data() + solution.size());
  start_derivatives_.clear();
  end_derivatives_.clear();
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
  CheckDerivativeOrder(order, "GCVSpline");
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

// A cubic's knots where the pieces on either side differ in their second or third derivative
// (outside, the lines have neither), by more than 1e-9 of its largest f'' (or f''' over the
// knots' span): smaller differences are rounding.
std::vector<double> GCVSpline::Breakpoints() const {
  std::vector<double> points;
  if (half_order_ != 2) return points;
  const int last = static_cast<int>(x_.size()) - 1;
  const double span = x_[last] - x_[0];
  // f'' and f''' * span on either side of knot i (0 on the lines outside).
  const auto side = [&](int i, int piece, int order) {
    if (piece < 0 || piece == last) return 0.0;
    return CalcPiece(piece, x_[i], order) * (order == 3 ? span : 1.0);
  };
  double largest = 0.0;
  for (int i = 0; i <= last; ++i) {
    for (const int order : {2, 3}) {
      largest = std::max({largest, std::abs(side(i, i - 1, order)), std::abs(side(i, i, order))});
    }
  }
  for (int i = 0; i <= last; ++i) {
    for (const int order : {2, 3}) {
      if (std::abs(side(i, i - 1, order) - side(i, i, order)) > 1e-9 * largest) {
        points.push_back(x_[i]);
        break;
      }
    }
  }
  return points;
}

}  // namespace sinew::functions

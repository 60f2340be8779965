#include <sinew/engine/articulated_pivot.h>

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace sinew::engine {
namespace {
// Smallest pivot, relative to the block's scale, that the small system may have.
constexpr double kMinPivot = 1e-14;

}  // namespace

bool Invert3(const Mat3& A, Mat3& inverse) {
  // The cofactors once, for the determinant and the inverse both.
  const double scale = A.cwiseAbs().maxCoeff();
  double det = 0.0;
  bool invertible = false;
  A.computeInverseAndDetWithCheck(inverse, det, invertible, 1e-10 * scale * scale * scale);
  return invertible;
}

bool ArticulatedPivot::Factorize(const Block& K, int nu) {
  nu_ = nu;
  nc_ = static_cast<int>(K.rows()) - 12 - nu;
  const int rows = 6 + nu;  // first joint row
  const Eigen::Matrix<double, 6, 6> J_B = K.block<6, 6>(rows, 0);
  Mat3 A_inv, C_inv;
  if (!J_B.topRightCorner<3, 3>().isZero(0.0) || !Invert3(J_B.topLeftCorner<3, 3>(), A_inv)) {
    return false;
  }
  // A parameterized joint's two diagonal blocks are the same R^T: one inverse serves both.
  if (J_B.bottomRightCorner<3, 3>() == J_B.topLeftCorner<3, 3>()) {
    C_inv = A_inv;
  } else if (!Invert3(J_B.bottomRightCorner<3, 3>(), C_inv)) {
    return false;
  }
  Jinv_.topLeftCorner<3, 3>() = A_inv;
  Jinv_.topRightCorner<3, 3>().setZero();
  Jinv_.bottomRightCorner<3, 3>() = C_inv;
  Jinv_.bottomLeftCorner<3, 3>().noalias() = -C_inv * J_B.bottomLeftCorner<3, 3>() * A_inv;
  M_ = K.topLeftCorner<6, 6>();
  fixed_nu_ = 0;
  all_locked_ = false;
  if (nc_ == 0) {
    switch (nu_) {
      case 1:
        return FactorizeFixed<1>(K);
      case 2:
        return FactorizeFixed<2>(K);
      case 3:
        return FactorizeFixed<3>(K);
      default:
        break;
    }
  }
  S_.noalias() = -Jinv_ * K.block(rows, 6, 6, nu);
  MS_.noalias() = M_ * S_;
  if (nu_ + nc_ == 0) return true;  // the joint rows alone fix the twist
  const double inertia_scale = InertiaScale(S_);
  all_locked_ = FindLockedSpeeds(K, inertia_scale);
  if (all_locked_) {
    D_.topLeftCorner(nu_, nu_).noalias() = S_.transpose() * MS_;
    return true;
  }
  Small small(nu_ + nc_, nu_ + nc_);
  small.topLeftCorner(nu_, nu_).noalias() = S_.transpose() * MS_;
  small.topRightCorner(nu_, nc_) = K.block(12 + nu_, 6, nc_, nu_).transpose();
  small.bottomLeftCorner(nc_, nu_) = K.block(12 + nu_, 6, nc_, nu_);
  small.bottomRightCorner(nc_, nc_).setZero();
  if (!small_) small_ = std::make_unique<Eigen::PartialPivLU<Small>>();
  small_->compute(small);
  const auto pivots = small_->matrixLU().diagonal().cwiseAbs();
  return pivots.minCoeff() > kMinPivot * std::max(pivots.maxCoeff(), inertia_scale);
}

bool ArticulatedPivot::FindLockedSpeeds(const Block& K, double inertia_scale) {
  if (nc_ != nu_) return false;
  const auto N = K.block(12 + nu_, 6, nc_, nu_);
  std::array<bool, 6> taken{};
  double largest = 0.0, smallest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < nc_; ++i) {
    int column = -1;
    for (int k = 0; k < nu_; ++k) {
      if (N(i, k) == 0.0) continue;
      if (column >= 0) return false;  // a row mixing speeds
      column = k;
    }
    if (column < 0 || taken[column]) return false;
    taken[column] = true;
    locked_speed_[i] = column;
    lock_scale_[i] = N(i, column);
    largest = std::max(largest, std::abs(lock_scale_[i]));
    smallest = std::min(smallest, std::abs(lock_scale_[i]));
  }
  // The small system's determinant is det(N)^2: the generic LU's pivot test, on N's entries.
  return smallest > kMinPivot * std::max(largest, inertia_scale);
}

template <typename SMatrix>
double ArticulatedPivot::InertiaScale(const SMatrix& S) const {
  return M_.cwiseAbs().maxCoeff() * S.colwise().squaredNorm().maxCoeff();
}

template <int NU>
bool ArticulatedPivot::FactorizeFixed(const Block& K) {
  using MatNU = Eigen::Matrix<double, NU, NU>;
  const Eigen::Matrix<double, 6, NU> S = -Jinv_.lazyProduct(K.template block<6, NU>(6 + NU, 6));
  const Eigen::Matrix<double, 6, NU> MS = M_.lazyProduct(S);
  S_ = S;
  MS_ = MS;
  const double inertia_scale = InertiaScale(S);
  const MatNU D = S.transpose().lazyProduct(MS);
  const Eigen::LLT<MatNU> llt(D);
  // The Cholesky pivots L_ii^2 are those of an LU without row exchanges; D is symmetric
  // positive definite when the joint's free directions carry inertia.
  const Eigen::Matrix<double, NU, 1> pivots = llt.matrixLLT().diagonal().cwiseAbs2();
  if (llt.info() != Eigen::Success ||
      !(pivots.minCoeff() > kMinPivot * std::max(pivots.maxCoeff(), inertia_scale))) {
    return false;
  }
  // D^-1 = L^-T L^-1, L^-1 by forward substitution with every size fixed (the LLT's solve on an
  // identity goes through Eigen's blocked triangular solver, which costs more than this).
  const MatNU& L = llt.matrixLLT();  // its lower triangle is L
  MatNU L_inv = MatNU::Zero();
  for (int j = 0; j < NU; ++j) {
    L_inv(j, j) = 1.0 / L(j, j);
    for (int i = j + 1; i < NU; ++i) {
      double sum = 0.0;
      for (int k = j; k < i; ++k) sum += L(i, k) * L_inv(k, j);
      L_inv(i, j) = -sum / L(i, i);
    }
  }
  Dinv_.template topLeftCorner<NU, NU>().noalias() = L_inv.transpose().lazyProduct(L_inv);
  fixed_nu_ = NU;
  return true;
}

}  // namespace sinew::engine

// The pivot block of a tree node whose joint rows fix the body's twist from its parent's twist
// and the joint speeds (a parameterized joint: the joint rows' block J_B on the twist is square
// and invertible), eliminated as in the articulated-body algorithm instead of by a generic LU.
//
// The node's unknowns are, in order, the body twist V (6), the joint speeds u (nu), the joint
// rows' multipliers lambda (6) and the multipliers mu of the coordinate rows on u (nc: locks,
// prescribed motion). Its pivot block (M_A: the body's articulated inertia) is
//   [ M_A   0     J_B^T  0   ]
//   [ 0     0     J_u^T  N^T ]
//   [ J_B   J_u   0      0   ]
//   [ 0     N     0      0   ].
// The joint rows give V = S u + a, with the motion subspace S = -J_B^-1 J_u (6 x nu) and
// a = J_B^-1 r_lambda; the body rows then give lambda = J_B^-T (r_V - M_A V), and what is left
// is a small KKT system on the joint speeds (at most 12 x 12):
//   [ D  N^T ] [u ]   [ r_u + S^T (r_V - M_A a) ]
//   [ N  0   ] [mu] = [ r_mu                    ],   D = S^T M_A S.
// The block couples to the parent's twist only through the joint rows (their block J_P on it), so
// W = K^-1 C and the parent's update C^T W follow in closed form: with the shift
// A = J_B^-1 J_P (V = S u - A V_P when the joint rows' right-hand side is zero),
//   Z = [D N^T; N 0]^-1 [-S^T M_A A; 0],   W = [A + S Z_u; Z_u; J_B^-T (-M_A A - M_A S Z_u); Z_mu],
//   C^T W = -(A^T M_A A + (S^T M_A A)^T Z_u) = -T^T (M_A - M_A S P S^T M_A) T,
// T = -A and P the speeds' block of the small system's inverse (D^-1 without coordinate rows):
// the parent gains the body's articulated inertia seen through the rigid shift, as in the
// articulated-body algorithm, with one 6-column solve of the small system instead of six solves
// of the whole block.
// J_B of a parameterized joint is block lower triangular, [R^T 0; -R^T [r]x R^T] in 3 x 3
// blocks (also when the joint is reversed), so J_B^-1 takes two 3 x 3 inverses. And the joint
// rows hold when the body moves rigidly with its parent (u = 0: the same angular velocity, the
// parent's linear velocity carried to the body's origin), so the shift is
// A = -[I 0; -[p_B - p_P]x I] = [-I 0; K -I]: SolveCoupling computes K alone and takes the
// rest as it is (ArticulatedPivotTest checks the result against six solves and a dense LU).
#pragma once

#include <sinew/math/types.h>

#include <Eigen/LU>
#include <array>
#include <memory>

namespace sinew::engine {

/// Inverse of a 3 x 3 block of a joint's rows into `inverse`; false when it is (nearly) singular
/// (determinant below 1e-10 of its largest entry cubed).
bool Invert3(const Mat3& A, Mat3& inverse);

/// Factorization and solves of one articulated pivot block (layout above). Fixed capacity: no
/// heap use.
class ArticulatedPivot {
 public:
  /// A node block (at most 24 x 24): a view of where TreeKktSolver keeps it.
  using Block = Eigen::Ref<const MatX>;

  /// Factorizes `K` with `nu` joint speeds (the rest of its rows past the joint rows are
  /// coordinate rows). Returns false, and the caller must use a generic factorization, when J_B
  /// is not block lower triangular and invertible or the small system's pivots fall below 1e-14
  /// of its scale (a singular or nearly singular block: the generic LU then decides).
  bool Factorize(const Block& K, int nu);

  /// Solves K x = r in place for one or more right-hand sides (columns of `x`, at most 6).
  template <typename Rhs>
  void SolveInPlace(Eigen::MatrixBase<Rhs>& x) const;

  /// For a coupling C to the parent's twist that is zero outside the joint rows, where it is
  /// `J_P` (6 x 6): W = K^-1 C into `W` (K's rows, 6 columns) and C^T W into `CtW`, in closed
  /// form (above). Same result as SolveInPlace on C, without its six solves of the whole block.
  template <typename WMatrix>
  void SolveCoupling(const Eigen::Matrix<double, 6, 6>& J_P, Eigen::MatrixBase<WMatrix>& W,
                     Eigen::Matrix<double, 6, 6>& CtW) const;

 private:
  using Six = Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, 6>;
  using Small = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 12, 12>;
  using SmallRhs = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 12, 6>;
  int nu_ = 0, nc_ = 0;
  // nu_ when the small system is D alone (no coordinate rows) with 1 to 3 speeds, the common
  // case (CustomJoints): the solves then use D^-1 (from D's Cholesky factor) with every size
  // known at compile time; 0 otherwise (the small LU below).
  int fixed_nu_ = 0;
  Mat3 Dinv_ = Mat3::Zero();  // D^-1 in its top-left fixed_nu_ x fixed_nu_ corner
  Eigen::Matrix<double, 6, 6> M_ = Eigen::Matrix<double, 6, 6>::Zero();     // M_A
  Eigen::Matrix<double, 6, 6> Jinv_ = Eigen::Matrix<double, 6, 6>::Zero();  // J_B^-1
  Six S_, MS_;                                                              // S and M_A S
  // [D N^T; N 0]'s LU, made on the first factorization that needs it (a joint with coordinate
  // rows, or more than 3 speeds): kept apart, as most nodes never use its 1.3 kB, and a long
  // chain's pivots then fit the cache better.
  std::unique_ptr<Eigen::PartialPivLU<Small>> small_;
  // Every speed locked or prescribed one by one (a locked joint, e.g. a hung skeleton's pelvis):
  // N is square with one nonzero per row, N(i, locked_speed_[i]) = lock_scale_[i], in distinct
  // columns. Then [D N^T; N 0] is solved without a factorization: u = N^-1 y_mu and
  // mu = N^-T (y_u - D u), with D_ = S^T M_A S kept.
  bool all_locked_ = false;
  std::array<int, 6> locked_speed_{};
  std::array<double, 6> lock_scale_{};
  Eigen::Matrix<double, 6, 6> D_ = Eigen::Matrix<double, 6, 6>::Zero();
  // Whether the coordinate rows of K (nc_ = nu_) lock every speed one by one; fills the above.
  bool FindLockedSpeeds(const Block& K, double inertia_scale);
  // y = [D N^T; N 0]^-1 y in place with small_'s factors (substitution written out: Eigen's
  // blocked triangular solves cost more than the arithmetic on these few rows).
  template <typename Y>
  void SolveSmallInPlace(Y& y) const;
  // D's scale, that of M_A seen through S: a pivot far below it means a direction with
  // (nearly) no inertia that the joint leaves free.
  template <typename SMatrix>
  double InertiaScale(const SMatrix& S) const;
  // S, M_A S, and D's Cholesky check and inverse for fixed_nu_ = NU (no coordinate rows), with
  // sizes known at compile time; false when a pivot is below the scale.
  template <int NU>
  bool FactorizeFixed(const Block& K);
  template <int NU, typename WMatrix>
  void SolveCouplingFixed(const Mat3& K, const Eigen::Matrix<double, 6, 6>& MA,
                          Eigen::MatrixBase<WMatrix>& W, Eigen::Matrix<double, 6, 6>& CtW) const;
  template <int NU, typename Rhs>
  void SolveInPlaceFixed(Eigen::MatrixBase<Rhs>& x) const;
  // Y^T = A^T M_A S = [-(M_A S)_1 + K^T (M_A S)_2; -(M_A S)_2] (6 x nu) into `Yt`.
  template <typename MSMatrix, typename YMatrix>
  static void ShiftedInertiaColumns(const Mat3& K, const MSMatrix& MS, YMatrix& Yt);
  // What both forms of SolveCoupling share once the speeds' block Z_u of the small system's
  // solution is known: C^T W, and W's twist, speed and joint rows.
  template <typename SMatrix, typename YMatrix, typename ZMatrix, typename WMatrix>
  void FinishCoupling(const SMatrix& S, const SMatrix& MS, const YMatrix& Yt, const ZMatrix& Zu,
                      const Mat3& K, const Eigen::Matrix<double, 6, 6>& MA,
                      Eigen::MatrixBase<WMatrix>& W, Eigen::Matrix<double, 6, 6>& CtW) const;
};

template <typename Y>
void ArticulatedPivot::SolveSmallInPlace(Y& y) const {
  const int n = nu_ + nc_;
  if (n == 0) return;
  if (all_locked_) {
    // u = N^-1 y_mu, then mu = N^-T (y_u - D u), row by row (N is a scaled permutation).
    Y u = y.topRows(nu_);  // y_u, kept for mu
    for (int i = 0; i < nc_; ++i) {
      y.row(locked_speed_[i]) = y.row(nu_ + i) / lock_scale_[i];
    }
    u.noalias() -= D_.topLeftCorner(nu_, nu_) * y.topRows(nu_);
    for (int i = 0; i < nc_; ++i) y.row(nu_ + i) = u.row(locked_speed_[i]) / lock_scale_[i];
    return;
  }
  y = small_->permutationP() * y;
  const Small& LU = small_->matrixLU();
  for (int i = 1; i < n; ++i) {
    for (int k = 0; k < i; ++k) y.row(i) -= LU(i, k) * y.row(k);
  }
  for (int i = n - 1; i >= 0; --i) {
    for (int k = i + 1; k < n; ++k) y.row(i) -= LU(i, k) * y.row(k);
    y.row(i) /= LU(i, i);
  }
}

template <typename WMatrix>
void ArticulatedPivot::SolveCoupling(const Eigen::Matrix<double, 6, 6>& J_P,
                                     Eigen::MatrixBase<WMatrix>& W,
                                     Eigen::Matrix<double, 6, 6>& CtW) const {
  using Mat6 = Eigen::Matrix<double, 6, 6>;
  // A = [-I 0; K -I] (the rigid shift, above): only K = X P_11 + C^-1 P_21 is computed, with
  // J_B^-1 = [A^-1 0; X C^-1] and J_P = [P_11 0; P_21 P_22]; every product with A is then one
  // 3 x 3 product, or none.
  const Mat3 K = Jinv_.bottomLeftCorner<3, 3>().lazyProduct(J_P.topLeftCorner<3, 3>()) +
                 Jinv_.bottomRightCorner<3, 3>().lazyProduct(J_P.bottomLeftCorner<3, 3>());
  Mat6 MA;  // M_A A
  MA.leftCols<3>() = M_.rightCols<3>().lazyProduct(K) - M_.leftCols<3>();
  MA.rightCols<3>() = -M_.rightCols<3>();
  switch (fixed_nu_) {
    case 1:
      return SolveCouplingFixed<1>(K, MA, W, CtW);
    case 2:
      return SolveCouplingFixed<2>(K, MA, W, CtW);
    case 3:
      return SolveCouplingFixed<3>(K, MA, W, CtW);
    default:
      break;
  }
  // Z_u's right-hand side is -Y (ShiftedInertiaColumns).
  Six Yt(6, nu_);
  ShiftedInertiaColumns(K, MS_, Yt);
  SmallRhs Z(nu_ + nc_, 6);
  Z.topRows(nu_) = -Yt.transpose();
  Z.bottomRows(nc_).setZero();
  SolveSmallInPlace(Z);
  FinishCoupling(S_, MS_, Yt, Z.topRows(nu_), K, MA, W, CtW);
  W.bottomRows(nc_) = Z.bottomRows(nc_);
}

template <int NU, typename WMatrix>
void ArticulatedPivot::SolveCouplingFixed(const Mat3& K, const Eigen::Matrix<double, 6, 6>& MA,
                                          Eigen::MatrixBase<WMatrix>& W,
                                          Eigen::Matrix<double, 6, 6>& CtW) const {
  // SolveCoupling's steps with D^-1 for the small system and every size fixed.
  const auto S = S_.template leftCols<NU>();
  const auto MS = MS_.template leftCols<NU>();
  Eigen::Matrix<double, 6, NU> Yt;
  ShiftedInertiaColumns(K, MS, Yt);
  const Eigen::Matrix<double, NU, 6, NU == 1 ? Eigen::RowMajor : 0> Zu =
      -Dinv_.template topLeftCorner<NU, NU>().lazyProduct(Yt.transpose());
  FinishCoupling(S, MS, Yt, Zu, K, MA, W, CtW);
}

template <typename MSMatrix, typename YMatrix>
void ArticulatedPivot::ShiftedInertiaColumns(const Mat3& K, const MSMatrix& MS, YMatrix& Yt) {
  Yt.template topRows<3>() = K.transpose().lazyProduct(MS.template bottomRows<3>());
  Yt.template topRows<3>() -= MS.template topRows<3>();
  Yt.template bottomRows<3>() = -MS.template bottomRows<3>();
}

template <typename SMatrix, typename YMatrix, typename ZMatrix, typename WMatrix>
void ArticulatedPivot::FinishCoupling(const SMatrix& S, const SMatrix& MS, const YMatrix& Yt,
                                      const ZMatrix& Zu, const Mat3& K,
                                      const Eigen::Matrix<double, 6, 6>& MA,
                                      Eigen::MatrixBase<WMatrix>& W,
                                      Eigen::Matrix<double, 6, 6>& CtW) const {
  const int nu = static_cast<int>(Zu.rows());
  // C^T W = -(A^T M_A A + Y^T Z_u).
  CtW.template topRows<3>() = MA.template topRows<3>();
  CtW.template topRows<3>().noalias() -= K.transpose().lazyProduct(MA.template bottomRows<3>());
  CtW.template bottomRows<3>() = MA.template bottomRows<3>();
  CtW.noalias() -= Yt.lazyProduct(Zu);
  // W's twist rows A + S Z_u, its joint rows J_B^-T (-M_A A - M_A S Z_u).
  W.template topRows<6>().noalias() = S.lazyProduct(Zu);
  W.template topLeftCorner<3, 3>() -= Mat3::Identity();
  W.template block<3, 3>(3, 0) += K;
  W.template block<3, 3>(3, 3) -= Mat3::Identity();
  W.template middleRows<ZMatrix::RowsAtCompileTime>(6, nu) = Zu;
  Eigen::Matrix<double, 6, 6> r = -MA;
  r.noalias() -= MS.lazyProduct(Zu);
  auto lambda = W.template middleRows<6>(6 + nu);
  lambda.template topRows<3>().noalias() =
      Jinv_.topLeftCorner<3, 3>().transpose().lazyProduct(r.template topRows<3>());
  lambda.template topRows<3>().noalias() +=
      Jinv_.bottomLeftCorner<3, 3>().transpose().lazyProduct(r.template bottomRows<3>());
  lambda.template bottomRows<3>().noalias() =
      Jinv_.bottomRightCorner<3, 3>().transpose().lazyProduct(r.template bottomRows<3>());
}

template <int NU, typename Rhs>
void ArticulatedPivot::SolveInPlaceFixed(Eigen::MatrixBase<Rhs>& x) const {
  // SolveInPlace's steps with D^-1 for the small system and every size fixed.
  constexpr int kCols = Rhs::ColsAtCompileTime;
  constexpr int kMaxCols = kCols == 1 ? 1 : 6;
  using SixCols = Eigen::Matrix<double, 6, kCols, 0, 6, kMaxCols>;
  using SpeedCols =
      Eigen::Matrix<double, NU, kCols, (NU == 1 && kCols != 1) ? Eigen::RowMajor : 0, NU, kMaxCols>;
  const auto S = S_.template leftCols<NU>();
  const auto MS = MS_.template leftCols<NU>();
  const SixCols a = Jinv_.lazyProduct(x.template middleRows<6>(6 + NU));
  SixCols t = x.template topRows<6>();
  t.noalias() -= M_.lazyProduct(a);
  SpeedCols rhs = x.template middleRows<NU>(6);
  rhs.noalias() += S.transpose().lazyProduct(t);
  const SpeedCols y = Dinv_.template topLeftCorner<NU, NU>().lazyProduct(rhs);
  x.template topRows<6>() = a;
  x.template topRows<6>().noalias() += S.lazyProduct(y);
  t.noalias() -= MS.lazyProduct(y);
  x.template middleRows<6>(6 + NU).noalias() = Jinv_.transpose().lazyProduct(t);
  x.template middleRows<NU>(6) = y;
}

template <typename Rhs>
void ArticulatedPivot::SolveInPlace(Eigen::MatrixBase<Rhs>& x) const {
  switch (fixed_nu_) {
    case 1:
      return SolveInPlaceFixed<1>(x);
    case 2:
      return SolveInPlaceFixed<2>(x);
    case 3:
      return SolveInPlaceFixed<3>(x);
    default:
      break;
  }
  // Fixed-size temporaries for one right-hand side (the tree solve's vectors).
  constexpr int kCols = Rhs::ColsAtCompileTime;
  constexpr int kMaxCols = kCols == 1 ? 1 : 6;
  using SixCols = Eigen::Matrix<double, 6, kCols, 0, 6, kMaxCols>;
  using SmallCols = Eigen::Matrix<double, Eigen::Dynamic, kCols, 0, 12, kMaxCols>;
  const int m = static_cast<int>(x.cols());
  const SixCols a = Jinv_.lazyProduct(x.template middleRows<6>(6 + nu_));
  SixCols t = x.template topRows<6>();
  t.noalias() -= M_.lazyProduct(a);
  SmallCols y(nu_ + nc_, m);
  y.topRows(nu_) = x.middleRows(6, nu_);
  y.topRows(nu_).noalias() += S_.transpose().lazyProduct(t);
  y.bottomRows(nc_) = x.bottomRows(nc_);
  SolveSmallInPlace(y);
  x.template topRows<6>() = a;
  x.template topRows<6>().noalias() += S_.lazyProduct(y.topRows(nu_));
  t.noalias() -= MS_.lazyProduct(y.topRows(nu_));
  x.template middleRows<6>(6 + nu_).noalias() = Jinv_.transpose().lazyProduct(t);
  x.middleRows(6, nu_) = y.topRows(nu_);
  x.bottomRows(nc_) = y.bottomRows(nc_);
}

}  // namespace sinew::engine

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
// J_B of a parameterized joint is block lower triangular, [R^T 0; -R^T [r]x R^T] in 3 x 3
// blocks (also when the joint is reversed), so J_B^-1 takes two 3 x 3 inverses.
#pragma once

#include <sinew/math/types.h>

#include <Eigen/LU>

namespace sinew::engine {

/// Factorization and solves of one articulated pivot block (layout above). Fixed capacity: no
/// heap use.
class ArticulatedPivot {
 public:
  /// A node block (at most 24 x 24), as TreeKktSolver holds it.
  using Block = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 24, 24>;

  /// Factorizes `K` with `nu` joint speeds (the rest of its rows past the joint rows are
  /// coordinate rows). Returns false, and the caller must use a generic factorization, when J_B
  /// is not block lower triangular and invertible or the small system's pivots fall below 1e-14
  /// of its scale (a singular or nearly singular block: the generic LU then decides).
  bool Factorize(const Block& K, int nu);

  /// Solves K x = r in place for one or more right-hand sides (columns of `x`, at most 6).
  template <typename Rhs>
  void SolveInPlace(Eigen::MatrixBase<Rhs>& x) const;

 private:
  using Six = Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, 6>;
  using Small = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 12, 12>;
  using SmallRhs = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 12, 6>;
  int nu_ = 0, nc_ = 0;
  Eigen::Matrix<double, 6, 6> M_ = Eigen::Matrix<double, 6, 6>::Zero();     // M_A
  Eigen::Matrix<double, 6, 6> Jinv_ = Eigen::Matrix<double, 6, 6>::Zero();  // J_B^-1
  Six S_, MS_;                                                              // S and M_A S
  Eigen::PartialPivLU<Small> small_;                                        // [D N^T; N 0]
};

template <typename Rhs>
void ArticulatedPivot::SolveInPlace(Eigen::MatrixBase<Rhs>& x) const {
  const int m = static_cast<int>(x.cols());
  const Six a = Jinv_ * x.middleRows(6 + nu_, 6);
  const Six t = x.template topRows<6>() - M_ * a;
  SmallRhs y(nu_ + nc_, m);
  y.topRows(nu_) = x.middleRows(6, nu_);
  y.topRows(nu_).noalias() += S_.transpose() * t;
  y.bottomRows(nc_) = x.bottomRows(nc_);
  if (nu_ + nc_ > 0) {
    const SmallRhs z = small_.solve(y);
    y = z;
  }
  x.template topRows<6>() = a;
  x.template topRows<6>().noalias() += S_ * y.topRows(nu_);
  Six r = t;
  r.noalias() -= MS_ * y.topRows(nu_);
  x.middleRows(6 + nu_, 6).noalias() = Jinv_.transpose() * r;
  x.middleRows(6, nu_) = y.topRows(nu_);
  x.bottomRows(nc_) = y.bottomRows(nc_);
}

}  // namespace sinew::engine

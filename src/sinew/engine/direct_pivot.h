// The pivot block of a tree node whose body hangs on a direct Cartesian joint (Pin, Ball,
// Universal, Weld): no joint speeds among its unknowns, only the body twist V (6) and the
// multipliers lambda of the joint's m rows (m = 6 minus the joint's degrees of freedom d):
//   [ M_A  J_B^T ] [V     ]   [r_V     ]
//   [ J_B  0     ] [lambda] = [r_lambda],
// M_A the body's articulated inertia, J_B the joint rows' block on the twist (m x 6). Eliminated
// as in the articulated-body algorithm instead of by a generic LU of the whole block.
// A FrameConstraint's rows are three point rows [P  s I] (s = 1 on the joint's child, -1 on a
// reversed joint's parent) and m - 3 rotation rows [Q  0]. Completing Q with d rows E to an
// invertible 3 x 3 block Q_E = [Q; E] gives an invertible 6 x 6 [J_B; E 0], whose inverse
//   [ 0    Q_E^-1        ]
//   [ s I  -s P Q_E^-1   ]
// holds a right inverse G of J_B (its first m columns: J_B G = I) and a basis N of J_B's null
// space, the joint's free motions (its last d columns). Then, with D = N^T M_A N (d x d: the
// inertia the joint leaves free, well conditioned however large M_A grows along a chain),
//   a = G r_lambda,  t = r_V - M_A a,  alpha = D^-1 N^T t,
//   V = a + N alpha,  lambda = G^T (t - M_A N alpha).
// The block couples to the parent's twist only through the joint rows (their block J_P), so
// W = K^-1 C and the parent's update follow in closed form: with A = G J_P, Y = N^T M_A A and
// Z = D^-1 Y,
//   W = [A - N Z; G^T (M_A N Z - M_A A)],   C^T W = -(A^T M_A A - Y^T Z),
// the parent gains the body's inertia less what the joint's free motions keep from it.
#pragma once

#include <sinew/math/types.h>

#include <Eigen/Core>

namespace sinew::engine {

/// Factorization and solves of one direct-joint pivot block (layout above). Fixed capacity: no
/// heap use.
class DirectPivot {
 public:
  /// A node block (at most 24 x 24): a view of where TreeKktSolver keeps it.
  using Block = Eigen::Ref<const MatX>;

  /// Factorizes `K` (6 + m rows, m the joint rows, 3 <= m <= 6). Returns false, and the caller
  /// must use a generic factorization, when the joint rows do not have the layout above with an
  /// invertible Q_E, or D's pivots fall below 1e-14 of its scale (a free motion without
  /// inertia: the generic LU then decides).
  bool Factorize(const Block& K);

  /// Solves K x = r in place for one or more right-hand sides (columns of `x`, at most 6).
  template <typename Rhs>
  void SolveInPlace(Eigen::MatrixBase<Rhs>& x) const;

  /// For a coupling C to the parent's twist that is zero outside the joint rows, where it is
  /// `J_P` (m x 6): W = K^-1 C into `W` (K's rows, 6 columns) and C^T W into `CtW`, in closed
  /// form (above).
  template <typename JMatrix, typename WMatrix>
  void SolveCoupling(const Eigen::MatrixBase<JMatrix>& J_P, Eigen::MatrixBase<WMatrix>& W,
                     Eigen::Matrix<double, 6, 6>& CtW) const;

 private:
  // Fixed sizes, zero-padded (G's columns past m, N's and D^-1's past d are zero), so that every
  // product is a fixed-size one: Eigen's runtime size dispatch costs more than the arithmetic.
  using Mat6 = Eigen::Matrix<double, 6, 6>;
  using Mat63 = Eigen::Matrix<double, 6, 3>;
  int m_ = 0;
  Mat6 M_ = Mat6::Zero();                         // M_A
  Mat6 G_ = Mat6::Zero();                         // G
  Mat63 N_ = Mat63::Zero(), MN_ = Mat63::Zero();  // N and M_A N
  Mat3 Dinv_ = Mat3::Zero();                      // D^-1
};

template <typename Rhs>
void DirectPivot::SolveInPlace(Eigen::MatrixBase<Rhs>& x) const {
  constexpr int kCols = Rhs::ColsAtCompileTime;
  constexpr int kMaxCols = kCols == 1 ? 1 : 6;
  using SixCols = Eigen::Matrix<double, 6, kCols, 0, 6, kMaxCols>;
  using ThreeCols = Eigen::Matrix<double, 3, kCols, 0, 3, kMaxCols>;
  SixCols lambda = SixCols::Zero(6, x.cols());
  lambda.topRows(m_) = x.bottomRows(m_);
  const SixCols a = G_.lazyProduct(lambda);
  SixCols t = x.template topRows<6>();
  t.noalias() -= M_.lazyProduct(a);
  const ThreeCols alpha = Dinv_.lazyProduct(N_.transpose().lazyProduct(t));
  x.template topRows<6>() = a;
  x.template topRows<6>().noalias() += N_.lazyProduct(alpha);
  t.noalias() -= MN_.lazyProduct(alpha);
  lambda.noalias() = G_.transpose().lazyProduct(t);
  x.bottomRows(m_) = lambda.topRows(m_);
}

template <typename JMatrix, typename WMatrix>
void DirectPivot::SolveCoupling(const Eigen::MatrixBase<JMatrix>& J_P,
                                Eigen::MatrixBase<WMatrix>& W,
                                Eigen::Matrix<double, 6, 6>& CtW) const {
  Mat6 J = Mat6::Zero();
  J.topRows(m_) = J_P;
  const Mat6 A = G_.lazyProduct(J);
  const Mat6 MA = M_.lazyProduct(A);
  const Eigen::Matrix<double, 3, 6> Y = MN_.transpose().lazyProduct(A);
  const Eigen::Matrix<double, 3, 6> Z = Dinv_.lazyProduct(Y);
  CtW.noalias() = -A.transpose().lazyProduct(MA);
  CtW.noalias() += Y.transpose().lazyProduct(Z);
  W.template topRows<6>() = A;
  W.template topRows<6>().noalias() -= N_.lazyProduct(Z);
  Mat6 r = -MA;
  r.noalias() += MN_.lazyProduct(Z);
  const Mat6 lambda = G_.transpose().lazyProduct(r);
  W.bottomRows(m_) = lambda.topRows(m_);
}

}  // namespace sinew::engine

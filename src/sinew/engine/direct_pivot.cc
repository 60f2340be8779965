#include <sinew/engine/articulated_pivot.h>
#include <sinew/engine/direct_pivot.h>

#include <Eigen/Cholesky>
#include <cmath>

namespace sinew::engine {
namespace {
// Smallest pivot of D, relative to its scale, that the elimination takes (as ArticulatedPivot).
constexpr double kMinPivot = 1e-14;

// The joint's rotation rows Q (0 to 3 rows on the angular velocity).
using RotationRows = Eigen::Matrix<double, Eigen::Dynamic, 3, 0, 3, 3>;

// Q with 3 - rows(Q) rows appended that complete it to a basis: the cross product of two
// rotation rows (pin), two directions across one (universal), or the axes (ball).
Mat3 CompleteRows(const RotationRows& Q) {
  Mat3 Q_E = Mat3::Identity();
  if (Q.rows() == 3) {
    Q_E = Q;
  } else if (Q.rows() == 2) {
    Q_E.topRows<2>() = Q;
    Q_E.row(2) = Vec3(Q.row(0)).cross(Vec3(Q.row(1))).transpose();
  } else if (Q.rows() == 1) {
    const Vec3 q = Q.row(0).transpose();
    int least = 0;
    q.cwiseAbs().minCoeff(&least);
    const Vec3 e1 = q.cross(Vec3::Unit(least)).normalized();
    Q_E.row(0) = q.transpose();
    Q_E.row(1) = e1.transpose();
    Q_E.row(2) = q.cross(e1).transpose();
  }
  return Q_E;
}
}  // namespace

bool DirectPivot::Factorize(const Block& K) {
  m_ = static_cast<int>(K.rows()) - 6;
  if (m_ < 3 || m_ > 6) return false;
  const auto J = K.bottomLeftCorner(m_, 6);
  const double s = J(0, 3);
  if (!(s == 1.0 || s == -1.0) || J.block<3, 3>(0, 3) != s * Mat3::Identity() ||
      !J.bottomRightCorner(m_ - 3, 3).isZero(0.0)) {
    return false;
  }
  Mat3 Q_E_inv;
  if (!Invert3(CompleteRows(J.bottomLeftCorner(m_ - 3, 3)), Q_E_inv)) return false;
  Mat6 J_E_inv;  // [J_B; E 0]^-1
  J_E_inv << Mat3::Zero(), Q_E_inv, s * Mat3::Identity(), -s * J.topLeftCorner<3, 3>() * Q_E_inv;
  const int d = 6 - m_;
  G_.setZero();
  G_.leftCols(m_) = J_E_inv.leftCols(m_);
  N_.setZero();
  N_.leftCols(d) = J_E_inv.rightCols(d);
  M_ = K.topLeftCorner<6, 6>();
  MN_.noalias() = M_ * N_;
  Dinv_.setZero();
  if (d == 0) return true;  // a weld: the joint rows alone fix the twist
  using Small = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 3>;
  const Small D = N_.leftCols(d).transpose() * MN_.leftCols(d);
  const Eigen::LLT<Small> llt(D);
  if (llt.info() != Eigen::Success) return false;
  // D's scale is that of M_A seen through N: a pivot far below it means a free motion with
  // (nearly) no inertia.
  const double scale = M_.cwiseAbs().maxCoeff() * N_.colwise().squaredNorm().maxCoeff();
  if (!(llt.matrixLLT().diagonal().minCoeff() > std::sqrt(kMinPivot * scale))) return false;
  Dinv_.topLeftCorner(d, d) = llt.solve(Small::Identity(d, d));
  return true;
}

}  // namespace sinew::engine

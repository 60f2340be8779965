#include <sinew/kinematics/euler_joint_models.h>
#include <sinew/kinematics/internal/joint_math.h>

namespace sinew::kinematics {

using internal::AngVelInParentFromBodyFixedXYZDot;
using internal::BodyFixedXYZ;
using internal::BodyFixedXYZDotFromAngVelInParent;

namespace {

// qdot of the three angles q[0..2] from w_FM in F held in u[0..2]; and the inverse.
void AnglesDot(std::span<const double> q, std::span<const double> u, std::span<double> qdot) {
  const Vec3 qd = BodyFixedXYZDotFromAngVelInParent(q[0], q[1], Vec3(u[0], u[1], u[2]));
  qdot[0] = qd.x();
  qdot[1] = qd.y();
  qdot[2] = qd.z();
}
void AngVel(std::span<const double> q, std::span<const double> qdot, std::span<double> u) {
  const Vec3 w = AngVelInParentFromBodyFixedXYZDot(q[0], q[1], Vec3(qdot[0], qdot[1], qdot[2]));
  u[0] = w.x();
  u[1] = w.y();
  u[2] = w.z();
}

}  // namespace

// ---- Ball ----
Transform BallJointModel::CalcX_FM(std::span<const double> q) const {
  return Transform::Rotation(BodyFixedXYZ(q[0], q[1], q[2]));
}
Mat6X BallJointModel::CalcH_FM(std::span<const double>) const {
  Mat6X H = Mat6X::Zero(6, 3);
  H.topRows<3>().setIdentity();
  return H;
}
void BallJointModel::CalcQDot(std::span<const double> q, std::span<const double> u,
                              std::span<double> qdot) const {
  AnglesDot(q, u, qdot);
}
void BallJointModel::CalcU(std::span<const double> q, std::span<const double> qdot,
                           std::span<double> u) const {
  AngVel(q, qdot, u);
}
SpatialVec BallJointModel::CalcHDotU(std::span<const double>, std::span<const double>) const {
  return SpatialVec::Zero();  // H is constant.
}

// ---- Free ----
Transform FreeJointModel::CalcX_FM(std::span<const double> q) const {
  return {BodyFixedXYZ(q[0], q[1], q[2]), Vec3(q[3], q[4], q[5])};
}
Mat6X FreeJointModel::CalcH_FM(std::span<const double>) const { return Mat6X::Identity(6, 6); }
void FreeJointModel::CalcQDot(std::span<const double> q, std::span<const double> u,
                              std::span<double> qdot) const {
  AnglesDot(q, u, qdot);
  for (int i = 3; i < 6; ++i) qdot[i] = u[i];
}
void FreeJointModel::CalcU(std::span<const double> q, std::span<const double> qdot,
                           std::span<double> u) const {
  AngVel(q, qdot, u);
  for (int i = 3; i < 6; ++i) u[i] = qdot[i];
}
SpatialVec FreeJointModel::CalcHDotU(std::span<const double>, std::span<const double>) const {
  return SpatialVec::Zero();  // H is the identity.
}

// ---- Ellipsoid ----
Transform EllipsoidJointModel::CalcX_FM(std::span<const double> q) const {
  Transform X;
  X.R = BodyFixedXYZ(q[0], q[1], q[2]);
  X.p = radii_.cwiseProduct(X.R.col(2));
  return X;
}
Mat6X EllipsoidJointModel::CalcH_FM(std::span<const double> q) const {
  // p_FM = r .* n with n = R_FM z, so v_FM = r .* (w_FM x n): column k is r .* (e_k x n).
  const Vec3 n = BodyFixedXYZ(q[0], q[1], q[2]).col(2);
  Mat6X H = Mat6X::Zero(6, 3);
  for (int k = 0; k < 3; ++k) {
    H(k, k) = 1.0;
    H.col(k).tail<3>() = radii_.cwiseProduct(Vec3::Unit(k).cross(n));
  }
  return H;
}
void EllipsoidJointModel::CalcQDot(std::span<const double> q, std::span<const double> u,
                                   std::span<double> qdot) const {
  AnglesDot(q, u, qdot);
}
void EllipsoidJointModel::CalcU(std::span<const double> q, std::span<const double> qdot,
                                std::span<double> u) const {
  AngVel(q, qdot, u);
}
SpatialVec EllipsoidJointModel::CalcV_FM(std::span<const double> q,
                                         std::span<const double> u) const {
  const Vec3 n = BodyFixedXYZ(q[0], q[1], q[2]).col(2);
  const Vec3 w(u[0], u[1], u[2]);
  SpatialVec V;
  V << w, radii_.cwiseProduct(w.cross(n));
  return V;
}

SpatialVec EllipsoidJointModel::CalcHDotU(std::span<const double> q,
                                          std::span<const double> u) const {
  // d/dt (r .* (w x n)) with wdot = 0: r .* (w x (w x n)).
  const Vec3 n = BodyFixedXYZ(q[0], q[1], q[2]).col(2);
  const Vec3 w(u[0], u[1], u[2]);
  SpatialVec A;
  A << Vec3::Zero(), radii_.cwiseProduct(w.cross(w.cross(n)));
  return A;
}

}  // namespace sinew::kinematics

#include <sinew/kinematics/internal/joint_math.h>
#include <sinew/kinematics/scapulothoracic_joint_model.h>

#include <cmath>
#include <numbers>

namespace sinew::kinematics {

using internal::AngVelInParentFromBodyFixedXYZDot;
using internal::BodyFixedXYZ;
using internal::BodyFixedXYZDotFromAngVelInParent;
using internal::RotationAboutUnitAxis;

namespace {
Mat3 Rz(double angle) { return RotationAboutUnitAxis(Vec3::UnitZ(), angle); }
}  // namespace

ScapulothoracicJointModel::ScapulothoracicJointModel(const Vec3& radii, double origin_x,
                                                     double origin_y, double direction)
    : radii_(radii.y(), radii.x(), radii.z()),
      origin_(origin_x, origin_y, 0.0),
      axis_(-std::sin(direction), std::cos(direction), 0.0),
      R_FF0_(Rz(std::numbers::pi / 2)) {}

ScapulothoracicJointModel::Parts ScapulothoracicJointModel::CalcParts(
    std::span<const double> q) const {
  Parts P;
  P.R_E = BodyFixedXYZ(q[0], q[1], q[2]);
  P.n = P.R_E.col(2);
  P.p_E = radii_.cwiseProduct(P.n);
  const Mat3 R_M0K = Rz(-std::numbers::pi / 2);  // massless body 1 in the ellipsoid's M0
  const Mat3 R_wing = RotationAboutUnitAxis(axis_, q[3]);
  P.R_C = R_M0K * R_wing;
  P.m = R_M0K * (R_wing * origin_);
  P.p_C = R_M0K * origin_ - P.m;
  P.w_C = R_M0K * axis_;
  return P;
}

Transform ScapulothoracicJointModel::CalcX_FM(std::span<const double> q) const {
  const Parts P = CalcParts(q);
  // X_F0M = E * C, then X_FM = Rz(pi/2) * X_F0M.
  return {R_FF0_ * P.R_E * P.R_C, R_FF0_ * (P.p_E + P.R_E * P.p_C)};
}

Mat6X ScapulothoracicJointModel::CalcH_FM(std::span<const double> q) const {
  const Parts P = CalcParts(q);
  const Vec3 r = P.R_E * P.p_C;  // from the ellipsoid point to M's origin, in F0
  Mat6X H(6, 4);
  for (int k = 0; k < 3; ++k) {
    const Vec3 e = Vec3::Unit(k);
    H.col(k) << R_FF0_ * e, R_FF0_ * (radii_.cwiseProduct(e.cross(P.n)) + e.cross(r));
  }
  // Winging: w = R_E w_C, v = R_E (-(w_C x m)).
  H.col(3) << R_FF0_ * (P.R_E * P.w_C), R_FF0_ * (P.R_E * (-P.w_C.cross(P.m)));
  return H;
}

void ScapulothoracicJointModel::CalcQDot(std::span<const double> q, std::span<const double> u,
                                         std::span<double> qdot) const {
  const Vec3 qd = BodyFixedXYZDotFromAngVelInParent(q[0], q[1], Vec3(u[0], u[1], u[2]));
  qdot[0] = qd.x();
  qdot[1] = qd.y();
  qdot[2] = qd.z();
  qdot[3] = u[3];
}

void ScapulothoracicJointModel::CalcU(std::span<const double> q, std::span<const double> qdot,
                                      std::span<double> u) const {
  const Vec3 w = AngVelInParentFromBodyFixedXYZDot(q[0], q[1], Vec3(qdot[0], qdot[1], qdot[2]));
  u[0] = w.x();
  u[1] = w.y();
  u[2] = w.z();
  u[3] = qdot[3];
}

SpatialVec ScapulothoracicJointModel::CalcHDotU(std::span<const double> q,
                                                std::span<const double> u) const {
  const Parts P = CalcParts(q);
  const Vec3 w_E(u[0], u[1], u[2]);
  const Vec3 r = P.R_E * P.p_C;
  // Winging relative motion (in M0), its bias with u3dot = 0.
  const Vec3 w_C = P.w_C * u[3];
  const Vec3 v_C = -w_C.cross(P.m);
  const Vec3 b_C = -w_C.cross(w_C.cross(P.m));
  // Ellipsoid bias: r .* (w x (w x n)).
  const Vec3 b_E = radii_.cwiseProduct(w_E.cross(w_E.cross(P.n)));
  // Compose the relative motions F0 -> M0 -> M (r = R_E p_C, all in F0):
  // a_w = w_E x (R_E w_C), a_v = b_E + w_E x (w_E x r) + 2 w_E x (R_E v_C) + R_E b_C.
  const Vec3 a_w = w_E.cross(P.R_E * w_C);
  const Vec3 a_v = b_E + w_E.cross(w_E.cross(r)) + 2.0 * w_E.cross(P.R_E * v_C) + P.R_E * b_C;
  SpatialVec A;
  A << R_FF0_ * a_w, R_FF0_ * a_v;
  return A;
}

}  // namespace sinew::kinematics

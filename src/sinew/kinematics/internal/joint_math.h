// Small inline helpers shared by the joint models: fast elementary rotations and the
// body-fixed X-Y-Z angle kinematics. Internal to the kinematics layer.
#pragma once

#include <sinew/math/types.h>

#include <cmath>

namespace sinew::kinematics::internal {

/// Rotation by `angle` (rad) about the unit vector `a` (Rodrigues' formula).
inline Mat3 RotationAboutUnitAxis(const Vec3& a, double angle) {
  const double c = std::cos(angle), s = std::sin(angle), t = 1.0 - c;
  Mat3 R;
  R << t * a.x() * a.x() + c, t * a.x() * a.y() - s * a.z(), t * a.x() * a.z() + s * a.y(),
      t * a.x() * a.y() + s * a.z(), t * a.y() * a.y() + c, t * a.y() * a.z() - s * a.x(),
      t * a.x() * a.z() - s * a.y(), t * a.y() * a.z() + s * a.x(), t * a.z() * a.z() + c;
  return R;
}

/// R = Rx(q0) Ry(q1) Rz(q2), body-fixed X-Y-Z angles in radians.
inline Mat3 BodyFixedXYZ(double q0, double q1, double q2) {
  const double c0 = std::cos(q0), s0 = std::sin(q0);
  const double c1 = std::cos(q1), s1 = std::sin(q1);
  const double c2 = std::cos(q2), s2 = std::sin(q2);
  Mat3 R;
  R << c1 * c2, -c1 * s2, s1,                                     //
      s0 * s1 * c2 + c0 * s2, -s0 * s1 * s2 + c0 * c2, -s0 * c1,  //
      -c0 * s1 * c2 + s0 * s2, c0 * s1 * s2 + s0 * c2, c0 * c1;
  return R;
}

/// The angle rates of body-fixed X-Y-Z angles q from the angular velocity w_FM expressed in F:
/// w_F = qd0 x + qd1 Rx(q0) y + qd2 Rx(q0) Ry(q1) z, inverted. Singular at q1 = +-pi/2.
inline Vec3 BodyFixedXYZDotFromAngVelInParent(double q0, double q1, const Vec3& w_F) {
  const double c0 = std::cos(q0), s0 = std::sin(q0);
  const double c1 = std::cos(q1), s1 = std::sin(q1);
  const double qd2 = (-s0 * w_F.y() + c0 * w_F.z()) / c1;
  const double qd1 = c0 * w_F.y() + s0 * w_F.z();
  const double qd0 = w_F.x() - s1 * qd2;
  return {qd0, qd1, qd2};
}

/// The angular velocity w_FM expressed in F from body-fixed X-Y-Z angle rates.
inline Vec3 AngVelInParentFromBodyFixedXYZDot(double q0, double q1, const Vec3& qd) {
  const double c0 = std::cos(q0), s0 = std::sin(q0);
  const double c1 = std::cos(q1), s1 = std::sin(q1);
  return {qd.x() + s1 * qd.z(), c0 * qd.y() - s0 * c1 * qd.z(), s0 * qd.y() + c0 * c1 * qd.z()};
}

}  // namespace sinew::kinematics::internal

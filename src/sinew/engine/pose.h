// Small helpers to read frames and velocities off a body state.
#pragma once

#include <sinew/engine/body.h>
#include <sinew/math/transform.h>

namespace sinew::engine {

/// X_GB of a body state.
inline Transform PoseOf(const BodyState& s) {
  return {s.quat_GB.normalized().toRotationMatrix(), s.p_GB};
}

/// Velocity (in G) of the point of body B at `p_GQ` (position in G).
inline Vec3 PointVelocity(const BodyState& s, const Vec3& p_GQ) {
  return s.v_GB + s.w_GB.cross(p_GQ - s.p_GB);
}

/// Rotation vector (axis * angle, |angle| <= pi) of a rotation matrix.
inline Vec3 RotationVector(const Mat3& R) {
  const Eigen::AngleAxisd aa(R);
  return aa.axis() * aa.angle();
}

/// The unit quaternion of the rotation by the rotation vector `theta` (rad).
inline Quat QuatFromRotationVector(const Vec3& theta) {
  const double angle = theta.norm();
  if (angle < 1e-300) return Quat::Identity();
  return Quat(Eigen::AngleAxisd(angle, theta / angle));
}

}  // namespace sinew::engine

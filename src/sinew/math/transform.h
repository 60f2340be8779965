// Rigid transforms X_AB = [R_AB; p_AB]: the pose of frame B in frame A.
#pragma once

#include <sinew/math/types.h>

namespace sinew {

/// The pose of a frame B in a frame A: `X_AB * p_B = R_AB * p_B + p_AB` gives a point of B in A.
/// Compose left to right: `X_AC = X_AB * X_BC`.
struct Transform {
  Mat3 R = Mat3::Identity();  ///< R_AB, columns are B's axes expressed in A.
  Vec3 p = Vec3::Zero();      ///< p_AB, B's origin from A's origin, expressed in A.

  Transform() = default;
  Transform(const Mat3& rotation, const Vec3& translation) : R(rotation), p(translation) {}

  static Transform Identity() { return {}; }
  static Transform Translation(const Vec3& p_AB) { return {Mat3::Identity(), p_AB}; }
  static Transform Rotation(const Mat3& R_AB) { return {R_AB, Vec3::Zero()}; }

  /// X_BA from X_AB.
  Transform Inverse() const {
    Mat3 Rt = R.transpose();
    return {Rt, -(Rt * p)};
  }
  /// X_AC = X_AB * X_BC.
  Transform operator*(const Transform& X_BC) const { return {R * X_BC.R, R * X_BC.p + p}; }
  /// A point given in B, re-expressed in A.
  Vec3 operator*(const Vec3& p_B) const { return R * p_B + p; }

  bool isApprox(const Transform& other, double tol = 1e-12) const {
    return R.isApprox(other.R, tol) && (p - other.p).norm() <= tol * (1 + p.norm());
  }
};

}  // namespace sinew

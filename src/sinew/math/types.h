// Basic linear-algebra types on Eigen. Spatial vectors put the angular part first:
// V = [w; v], F = [torque; force] (Simbody and Drake order).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace sinew {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;
using Vec6 = Eigen::Matrix<double, 6, 1>;
using SpatialVec = Vec6;  ///< [angular; linear]
using VecX = Eigen::VectorXd;
using MatX = Eigen::MatrixXd;
/// 6 x n with n <= 6 (a joint's H_FM): fixed capacity, so it never touches the heap.
using Mat6X = Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, 6>;

/// The matrix [v]x with [v]x * u = v x u.
inline Mat3 Skew(const Vec3& v) {
  Mat3 m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

}  // namespace sinew

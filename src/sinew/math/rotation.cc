#include <sinew/math/rotation.h>

#include <algorithm>
#include <cmath>

namespace sinew {

Mat3 RotationFromBodyFixedXYZ(const Vec3& angles) {
  return (Eigen::AngleAxisd(angles.x(), Vec3::UnitX()) *
          Eigen::AngleAxisd(angles.y(), Vec3::UnitY()) *
          Eigen::AngleAxisd(angles.z(), Vec3::UnitZ()))
      .toRotationMatrix();
}

Vec3 BodyFixedXYZFromRotation(const Mat3& R) {
  // For R = Rx(a) Ry(b) Rz(c): R(0,2) = sin b, R(1,2) = -sin a cos b, R(2,2) = cos a cos b,
  // R(0,1) = -cos b sin c, R(0,0) = cos b cos c.
  const double sin_b = std::clamp(R(0, 2), -1.0, 1.0);
  const double b = std::asin(sin_b);
  if (std::abs(sin_b) < 1.0 - 1e-12) {
    return {std::atan2(-R(1, 2), R(2, 2)), b, std::atan2(-R(0, 1), R(0, 0))};
  }
  // Gimbal lock: only a +- c is defined; put it all in a.
  return {std::atan2(R(2, 1), R(1, 1)), b, 0.0};
}

Mat3 BodyFixedXYZRatesFromAngularVelocity(const Vec3& angles) {
  // With R = Rx(a) Ry(b) Rz(c), w_M = adot (cb cc, -cb sc, sb) + bdot (sc, cc, 0) + cdot (0, 0, 1);
  // N is the inverse of that map.
  const double sb = std::sin(angles.y()), cb = std::cos(angles.y());
  const double sc = std::sin(angles.z()), cc = std::cos(angles.z());
  Mat3 N;
  N << cc / cb, -sc / cb, 0.0,  //
      sc, cc, 0.0,              //
      -sb * cc / cb, sb * sc / cb, 1.0;
  return N;
}

Mat3 RotationAboutAxis(const Vec3& axis, double angle) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

}  // namespace sinew

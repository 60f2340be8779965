#include <gtest/gtest.h>
#include <sinew/math/rotation.h>
#include <sinew/math/transform.h>

#include <cmath>

namespace sinew {
namespace {

TEST(RotationTest, BodyFixedXYZIsProductOfElementaryRotations) {
  const Vec3 a(0.3, -0.4, 1.1);
  // Rx(a) about the fixed x, then Ry about the new y, then Rz about the newest z.
  Mat3 Rx, Ry, Rz;
  Rx << 1, 0, 0, 0, std::cos(a.x()), -std::sin(a.x()), 0, std::sin(a.x()), std::cos(a.x());
  Ry << std::cos(a.y()), 0, std::sin(a.y()), 0, 1, 0, -std::sin(a.y()), 0, std::cos(a.y());
  Rz << std::cos(a.z()), -std::sin(a.z()), 0, std::sin(a.z()), std::cos(a.z()), 0, 0, 0, 1;
  EXPECT_TRUE(RotationFromBodyFixedXYZ(a).isApprox(Rx * Ry * Rz, 1e-15));
}

TEST(RotationTest, AnglesRoundTrip) {
  for (const Vec3& a : {Vec3(0.3, -0.4, 1.1), Vec3(-2.9, 1.2, 3.0), Vec3(0, 0, 0)}) {
    EXPECT_TRUE(BodyFixedXYZFromRotation(RotationFromBodyFixedXYZ(a)).isApprox(a, 1e-12))
        << a.transpose();
  }
}

TEST(RotationTest, AngleRatesFromAngularVelocityInvertTheDifferencedAngularVelocity) {
  // Along angles(t) = a + t r, the angular velocity in the rotated frame is the axial vector
  // of R^T dR/dt (central differences, error ~1e-12); N must map it back to r.
  const Vec3 a(0.3, -0.4, 1.1), r(0.7, -1.3, 0.4);
  constexpr double kStep = 1e-6;
  const Mat3 R = RotationFromBodyFixedXYZ(a);
  const Mat3 dR =
      (RotationFromBodyFixedXYZ(a + kStep * r) - RotationFromBodyFixedXYZ(a - kStep * r)) /
      (2 * kStep);
  const Mat3 W = R.transpose() * dR;  // [w_M]x
  const Vec3 w_M(W(2, 1), W(0, 2), W(1, 0));
  EXPECT_TRUE((BodyFixedXYZRatesFromAngularVelocity(a) * w_M).isApprox(r, 1e-9));
}

TEST(TransformTest, InverseAndComposition) {
  Transform X_AB(RotationFromBodyFixedXYZ(Vec3(0.1, 0.2, 0.3)), Vec3(1, 2, 3));
  Transform X_BC(RotationAboutAxis(Vec3(1, 1, 0), 0.7), Vec3(-1, 0.5, 2));
  EXPECT_TRUE((X_AB * X_AB.Inverse()).isApprox(Transform::Identity()));
  const Vec3 p_C(0.2, -0.3, 0.4);
  EXPECT_TRUE(((X_AB * X_BC) * p_C).isApprox(X_AB * (X_BC * p_C), 1e-14));
}

}  // namespace
}  // namespace sinew

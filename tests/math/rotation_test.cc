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

TEST(TransformTest, InverseAndComposition) {
  Transform X_AB(RotationFromBodyFixedXYZ(Vec3(0.1, 0.2, 0.3)), Vec3(1, 2, 3));
  Transform X_BC(RotationAboutAxis(Vec3(1, 1, 0), 0.7), Vec3(-1, 0.5, 2));
  EXPECT_TRUE((X_AB * X_AB.Inverse()).isApprox(Transform::Identity()));
  const Vec3 p_C(0.2, -0.3, 0.4);
  EXPECT_TRUE(((X_AB * X_BC) * p_C).isApprox(X_AB * (X_BC * p_C), 1e-14));
}

}  // namespace
}  // namespace sinew

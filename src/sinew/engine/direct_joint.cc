#include <sinew/engine/direct_joint.h>
#include <sinew/math/rotation.h>

#include <cmath>
#include <numbers>

namespace sinew::engine {
namespace {

// The angle equal to `angle` modulo 2 pi that is nearest to `previous`.
double Unwrap(double angle, double previous) {
  const double two_pi = 2 * std::numbers::pi;
  return angle + two_pi * std::round((previous - angle) / two_pi);
}

Mat3 Rx(double a) { return Eigen::AngleAxisd(a, Vec3::UnitX()).toRotationMatrix(); }

}  // namespace

int NumDirectCoordinates(JointForm form) {
  switch (form) {
    case JointForm::kPin:
      return 1;
    case JointForm::kBall:
      return 3;
    case JointForm::kUniversal:
      return 2;
    case JointForm::kWeld:
      return 0;
    case JointForm::kParameterized:
      break;
  }
  return -1;
}

Transform CalcDirectX_FM(JointForm form, std::span<const double> q) {
  switch (form) {
    case JointForm::kPin:
      return Transform::Rotation(Eigen::AngleAxisd(q[0], Vec3::UnitZ()).toRotationMatrix());
    case JointForm::kBall:
      return Transform::Rotation(RotationFromBodyFixedXYZ(Vec3(q[0], q[1], q[2])));
    case JointForm::kUniversal:
      return Transform::Rotation(Rx(q[0]) *
                                 Eigen::AngleAxisd(q[1], Vec3::UnitY()).toRotationMatrix());
    default:
      return Transform::Identity();
  }
}

Mat6X CalcDirectH_FM(JointForm form, std::span<const double> q) {
  const int n = NumDirectCoordinates(form);
  Mat6X H = Mat6X::Zero(6, n);
  switch (form) {
    case JointForm::kPin:
      H(2, 0) = 1;
      break;
    case JointForm::kBall:
      H.topRows<3>().setIdentity();
      break;
    case JointForm::kUniversal:
      H.block<3, 1>(0, 0) = Vec3::UnitX();
      H.block<3, 1>(0, 1) = Rx(q[0]) * Vec3::UnitY();
      break;
    default:
      break;
  }
  return H;
}

void ReadDirectCoordinates(JointForm form, const Transform& X_FM, const SpatialVec& V_FM_F,
                           std::span<double> q, std::span<double> u) {
  const Mat3& R = X_FM.R;
  const Vec3 w = V_FM_F.head<3>();
  switch (form) {
    case JointForm::kPin:
      q[0] = Unwrap(std::atan2(R(1, 0), R(0, 0)), q[0]);
      u[0] = w.z();
      break;
    case JointForm::kBall: {
      const Vec3 a = BodyFixedXYZFromRotation(R);
      for (int i = 0; i < 3; ++i) {
        q[i] = Unwrap(a[i], q[i]);
        u[i] = w[i];
      }
      break;
    }
    case JointForm::kUniversal: {
      // R = Rx(a) Ry(b): R(2,1) = sin a, R(1,1) = cos a, R(0,2) = sin b, R(0,0) = cos b.
      q[0] = Unwrap(std::atan2(R(2, 1), R(1, 1)), q[0]);
      q[1] = Unwrap(std::atan2(R(0, 2), R(0, 0)), q[1]);
      // w = adot x + bdot Rx(a) y, and x is perpendicular to Rx(a) y.
      u[0] = w.x();
      u[1] = w.dot(Rx(q[0]) * Vec3::UnitY());
      break;
    }
    default:
      break;
  }
}

}  // namespace sinew::engine

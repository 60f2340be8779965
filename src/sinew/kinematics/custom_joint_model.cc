#include <sinew/common/error.h>
#include <sinew/kinematics/custom_joint_model.h>
#include <sinew/kinematics/internal/joint_math.h>

#include <utility>

namespace sinew::kinematics {

using internal::RotationAboutUnitAxis;

namespace {
constexpr int kMaxArgs = 6;  // A joint has at most six coordinates.
}

CustomJointModel::CustomJointModel(std::array<TransformAxisTerm, 6> axes, int nq)
    : axes_(std::move(axes)), nq_(nq) {
  if (nq_ < 0 || nq_ > 6) throw Error("CustomJointModel: a joint has 0 to 6 coordinates");
  for (TransformAxisTerm& a : axes_) {
    const double n = a.axis.norm();
    if (!(n > 0.0)) throw Error("CustomJointModel: zero axis");
    a.axis /= n;
    for (int k : a.args) {
      if (k < 0 || k >= nq_) throw Error("CustomJointModel: axis argument out of range");
    }
    const bool needs_one = a.kind == TransformAxisTerm::Kind::kIdentity ||
                           a.kind == TransformAxisTerm::Kind::kFunction1;
    if (needs_one && a.args.size() != 1) throw Error("CustomJointModel: axis needs 1 argument");
    if (static_cast<int>(a.args.size()) > kMaxArgs) throw Error("CustomJointModel: too many args");
    if ((a.kind == TransformAxisTerm::Kind::kFunction1 ||
         a.kind == TransformAxisTerm::Kind::kFunctionN) &&
        !a.function) {
      throw Error("CustomJointModel: axis without function");
    }
  }
  for (int i = 0; i < 3; ++i) {
    rotation_fixed_[i] = axes_[i].kind == TransformAxisTerm::Kind::kConstant;
    fixed_rotation_[i] = RotationAboutUnitAxis(axes_[i].axis, axes_[i].value);
  }
}

Mat3 CustomJointModel::CalcAxisRotation(int i, double s) const {
  return rotation_fixed_[i] ? fixed_rotation_[i] : RotationAboutUnitAxis(axes_[i].axis, s);
}

void CustomJointModel::CalcS(std::span<const double> q, double* s) const {
  for (int i = 0; i < 6; ++i) {
    const TransformAxisTerm& a = axes_[i];
    switch (a.kind) {
      case TransformAxisTerm::Kind::kConstant:
        s[i] = a.value;
        break;
      case TransformAxisTerm::Kind::kIdentity:
        s[i] = q[a.args[0]];
        break;
      case TransformAxisTerm::Kind::kFunction1:
        s[i] = a.function->Calc(q[a.args[0]]);
        break;
      case TransformAxisTerm::Kind::kFunctionN: {
        double x[kMaxArgs];
        const int n = static_cast<int>(a.args.size());
        for (int k = 0; k < n; ++k) x[k] = q[a.args[k]];
        s[i] = a.function->CalcN(std::span<const double>(x, n));
        break;
      }
    }
  }
}

void CustomJointModel::CalcJ(std::span<const double> q, double (*J)[6]) const {
  for (int i = 0; i < 6; ++i) {
    for (int k = 0; k < 6; ++k) J[i][k] = 0.0;
    const TransformAxisTerm& a = axes_[i];
    switch (a.kind) {
      case TransformAxisTerm::Kind::kConstant:
        break;
      case TransformAxisTerm::Kind::kIdentity:
        J[i][a.args[0]] = 1.0;
        break;
      case TransformAxisTerm::Kind::kFunction1:
        J[i][a.args[0]] = a.function->CalcDerivative(q[a.args[0]], 1);
        break;
      case TransformAxisTerm::Kind::kFunctionN: {
        double x[kMaxArgs];
        const int n = static_cast<int>(a.args.size());
        for (int k = 0; k < n; ++k) x[k] = q[a.args[k]];
        for (int k = 0; k < n; ++k) {
          const int wrt[1] = {k};
          J[i][a.args[k]] += a.function->CalcPartialN(std::span<const double>(x, n), wrt);
        }
        break;
      }
    }
  }
}

double CustomJointModel::CalcSecondTerm(int i, std::span<const double> q,
                                        std::span<const double> u) const {
  const TransformAxisTerm& a = axes_[i];
  switch (a.kind) {
    case TransformAxisTerm::Kind::kConstant:
    case TransformAxisTerm::Kind::kIdentity:
      return 0.0;
    case TransformAxisTerm::Kind::kFunction1: {
      const double uk = u[a.args[0]];
      return a.function->CalcDerivative(q[a.args[0]], 2) * uk * uk;
    }
    case TransformAxisTerm::Kind::kFunctionN: {
      double x[kMaxArgs];
      const int n = static_cast<int>(a.args.size());
      for (int k = 0; k < n; ++k) x[k] = q[a.args[k]];
      double sum = 0.0;
      for (int k = 0; k < n; ++k) {
        for (int l = 0; l < n; ++l) {
          const int wrt[2] = {k, l};
          sum += a.function->CalcPartialN(std::span<const double>(x, n), wrt) * u[a.args[k]] *
                 u[a.args[l]];
        }
      }
      return sum;
    }
  }
  return 0.0;
}

void CustomJointModel::CalcRotationAxesInF(const double* s, Vec3* e, Mat3* R_FM) const {
  const Mat3 R1 = CalcAxisRotation(0, s[0]);
  const Mat3 R12 = R1 * CalcAxisRotation(1, s[1]);
  e[0] = axes_[0].axis;
  e[1] = R1 * axes_[1].axis;
  e[2] = R12 * axes_[2].axis;
  if (R_FM) *R_FM = R12 * CalcAxisRotation(2, s[2]);
}

Transform CustomJointModel::CalcX_FM(std::span<const double> q) const {
  double s[6];
  CalcS(q, s);
  Transform X;
  // Skip the constant zero rotations (every Pin, Slider, Universal, Planar joint has some).
  bool any = false;
  for (int i = 0; i < 3; ++i) {
    if (rotation_fixed_[i] && axes_[i].value == 0.0) continue;
    X.R = any ? Mat3(X.R * CalcAxisRotation(i, s[i])) : CalcAxisRotation(i, s[i]);
    any = true;
  }
  X.p = s[3] * axes_[3].axis + s[4] * axes_[4].axis + s[5] * axes_[5].axis;
  return X;
}

Mat6X CustomJointModel::CalcH_FM(std::span<const double> q) const {
  double s[6];
  CalcS(q, s);
  double J[6][6];
  CalcJ(q, J);
  Vec3 e[3];
  CalcRotationAxesInF(s, e, nullptr);
  // w_FM = sum_i sdot_i e_i (i = rotations), v_FM = sum_i sdot_i a_i (i = translations),
  // with sdot_i = sum_k J_ik u_k.
  Mat6X H = Mat6X::Zero(6, nq_);
  for (int k = 0; k < nq_; ++k) {
    for (int i = 0; i < 3; ++i) {
      H.col(k).head<3>() += J[i][k] * e[i];
      H.col(k).tail<3>() += J[i + 3][k] * axes_[i + 3].axis;
    }
  }
  return H;
}

SpatialVec CustomJointModel::CalcV_FM(std::span<const double> q, std::span<const double> u) const {
  double s[6];
  CalcS(q, s);
  double J[6][6];
  CalcJ(q, J);
  Vec3 e[3];
  CalcRotationAxesInF(s, e, nullptr);
  SpatialVec V = SpatialVec::Zero();
  for (int i = 0; i < 3; ++i) {
    double sdot_rot = 0.0, sdot_trans = 0.0;
    for (int k = 0; k < nq_; ++k) {
      sdot_rot += J[i][k] * u[k];
      sdot_trans += J[i + 3][k] * u[k];
    }
    V.head<3>() += sdot_rot * e[i];
    V.tail<3>() += sdot_trans * axes_[i + 3].axis;
  }
  return V;
}

void CustomJointModel::CalcQDot(std::span<const double>, std::span<const double> u,
                                std::span<double> qdot) const {
  for (int k = 0; k < nq_; ++k) qdot[k] = u[k];
}

void CustomJointModel::CalcU(std::span<const double>, std::span<const double> qdot,
                             std::span<double> u) const {
  for (int k = 0; k < nq_; ++k) u[k] = qdot[k];
}

SpatialVec CustomJointModel::CalcHDotU(std::span<const double> q, std::span<const double> u) const {
  double s[6];
  CalcS(q, s);
  double J[6][6];
  CalcJ(q, J);
  Vec3 e[3];
  CalcRotationAxesInF(s, e, nullptr);
  double sdot[6];
  for (int i = 0; i < 6; ++i) {
    sdot[i] = 0.0;
    for (int k = 0; k < nq_; ++k) sdot[i] += J[i][k] * u[k];
  }
  // d/dt e_2 = w_1 x e_2 with w_1 = sdot_1 e_1; d/dt e_3 = w_12 x e_3 with w_12 = w_1 + sdot_2 e_2.
  const Vec3 w1 = sdot[0] * e[0];
  const Vec3 w12 = w1 + sdot[1] * e[1];
  Vec3 a_w = sdot[1] * w1.cross(e[1]) + sdot[2] * w12.cross(e[2]);
  Vec3 a_v = Vec3::Zero();
  for (int i = 0; i < 3; ++i) {
    a_w += CalcSecondTerm(i, q, u) * e[i];
    a_v += CalcSecondTerm(i + 3, q, u) * axes_[i + 3].axis;
  }
  SpatialVec A;
  A << a_w, a_v;
  return A;
}

}  // namespace sinew::kinematics

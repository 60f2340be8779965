#include <sinew/common/error.h>
#include <sinew/functions/linear_function.h>
#include <sinew/kinematics/custom_joint_model.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace sinew::kinematics {

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
    // Most CustomJoints map coordinates through LinearFunctions (OpenSim's default for a
    // TransformAxis): evaluate those inline, slope q + intercept as LinearFunction does.
    const auto* linear = a.kind == TransformAxisTerm::Kind::kFunction1
                             ? dynamic_cast<const functions::LinearFunction*>(a.function.get())
                             : nullptr;
    if (linear && linear->slope() == 1.0 && linear->intercept() == 0.0) {
      a.kind = TransformAxisTerm::Kind::kIdentity;
    } else if (linear) {
      a.kind = TransformAxisTerm::Kind::kAffine;
      a.slope = linear->slope();
      a.value = linear->intercept();
    }
    has_curved_axes_ = has_curved_axes_ || a.kind == TransformAxisTerm::Kind::kFunction1 ||
                       a.kind == TransformAxisTerm::Kind::kFunctionN;
  }
  for (int i = 0; i < 3; ++i) {
    const TransformAxisTerm& a = axes_[i];
    rotation_zero_[i] = a.kind == TransformAxisTerm::Kind::kConstant && a.value == 0.0;
    fixed_cos_[i] = std::cos(a.value);
    fixed_sin_[i] = std::sin(a.value);
    coordinate_axis_[i] = -1;
    for (int k = 0; k < 3; ++k) {
      if (a.axis == Vec3::Unit(k)) coordinate_axis_[i] = k;
    }
  }
  int moving_rotations = 0;
  for (int i = 0; i < 3; ++i) {
    moving_rotations += axes_[i].kind == TransformAxisTerm::Kind::kConstant ? 0 : 1;
  }
  constant_H_ = !has_curved_axes_ && moving_rotations <= 1;
  if (!has_curved_axes_) {
    const double none[6] = {};  // any q: J is the same everywhere
    EvaluateJ(std::span<const double>(none, static_cast<size_t>(nq_)), constant_J_);
    if (constant_H_)
      constant_H_FM_ = EvaluateH_FM(std::span<const double>(none, static_cast<size_t>(nq_)));
  }
}

void CustomJointModel::CalcCosSin(int i, std::span<const double> q, double* c, double* s) const {
  if (axes_[i].kind == TransformAxisTerm::Kind::kConstant) {
    *c = fixed_cos_[i];
    *s = fixed_sin_[i];
    return;
  }
  const double angle = CalcAxisValue(i, q);
  *c = std::cos(angle);
  *s = std::sin(angle);
}

Vec3 CustomJointModel::RotateAbout(int i, double c, double s, const Vec3& v) const {
  const int k = coordinate_axis_[i];
  if (k >= 0) {
    // Elementary rotation about F's axis k: only the components (j, l) = (k+1, k+2) mix.
    const int j = (k + 1) % 3, l = (k + 2) % 3;
    Vec3 r;
    r[k] = v[k];
    r[j] = c * v[j] - s * v[l];
    r[l] = s * v[j] + c * v[l];
    return r;
  }
  // Rodrigues: R v = c v + s (a x v) + (1 - c) (a . v) a.
  const Vec3& a = axes_[i].axis;
  return c * v + s * a.cross(v) + ((1.0 - c) * a.dot(v)) * a;
}

void CustomJointModel::MultiplyByRotation(int i, double c, double s, Mat3& M) const {
  const int k = coordinate_axis_[i];
  if (k >= 0) {
    // M R_k: columns j and l mix, column k is unchanged.
    const int j = (k + 1) % 3, l = (k + 2) % 3;
    const Vec3 mj = M.col(j), ml = M.col(l);
    M.col(j) = c * mj + s * ml;
    M.col(l) = c * ml - s * mj;
    return;
  }
  const Vec3& a = axes_[i].axis;
  const double t = 1.0 - c;
  Mat3 R;
  R << t * a.x() * a.x() + c, t * a.x() * a.y() - s * a.z(), t * a.x() * a.z() + s * a.y(),
      t * a.x() * a.y() + s * a.z(), t * a.y() * a.y() + c, t * a.y() * a.z() - s * a.x(),
      t * a.x() * a.z() - s * a.y(), t * a.y() * a.z() + s * a.x(), t * a.z() * a.z() + c;
  M = M * R;
}

double CustomJointModel::CalcAxisValue(int i, std::span<const double> q) const {
  const TransformAxisTerm& a = axes_[i];
  switch (a.kind) {
    case TransformAxisTerm::Kind::kConstant:
      return a.value;
    case TransformAxisTerm::Kind::kIdentity:
      return q[a.args[0]];
    case TransformAxisTerm::Kind::kAffine:
      return a.slope * q[a.args[0]] + a.value;
    case TransformAxisTerm::Kind::kFunction1:
      return a.function->Calc(q[a.args[0]]);
    case TransformAxisTerm::Kind::kFunctionN: {
      double x[kMaxArgs];
      const int n = static_cast<int>(a.args.size());
      for (int k = 0; k < n; ++k) x[k] = q[a.args[k]];
      return a.function->CalcN(std::span<const double>(x, n));
    }
  }
  return 0.0;
}

void CustomJointModel::CalcJ(std::span<const double> q, double (*J)[6]) const {
  if (has_curved_axes_) {
    EvaluateJ(q, J);
  } else {
    std::copy(&constant_J_[0][0], &constant_J_[0][0] + 36, &J[0][0]);
  }
}

void CustomJointModel::EvaluateJ(std::span<const double> q, double (*J)[6]) const {
  for (int i = 0; i < 6; ++i) {
    for (int k = 0; k < 6; ++k) J[i][k] = 0.0;
    const TransformAxisTerm& a = axes_[i];
    switch (a.kind) {
      case TransformAxisTerm::Kind::kConstant:
        break;
      case TransformAxisTerm::Kind::kIdentity:
        J[i][a.args[0]] = 1.0;
        break;
      case TransformAxisTerm::Kind::kAffine:
        J[i][a.args[0]] = a.slope;
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
    case TransformAxisTerm::Kind::kAffine:
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

void CustomJointModel::CalcRotationAxesInF(std::span<const double> q, Vec3* e) const {
  double c1, s1, c2, s2;
  CalcCosSin(0, q, &c1, &s1);
  CalcCosSin(1, q, &c2, &s2);
  e[0] = axes_[0].axis;
  e[1] = RotateAbout(0, c1, s1, axes_[1].axis);
  e[2] = RotateAbout(0, c1, s1, RotateAbout(1, c2, s2, axes_[2].axis));
}

Transform CustomJointModel::CalcX_FM(std::span<const double> q) const {
  Transform X;
  X.R.setIdentity();
  // Skip the constant zero rotations (every Pin, Slider, Universal, Planar joint has some).
  for (int i = 0; i < 3; ++i) {
    if (rotation_zero_[i]) continue;
    double c, s;
    CalcCosSin(i, q, &c, &s);
    MultiplyByRotation(i, c, s, X.R);
  }
  X.p.setZero();
  for (int i = 3; i < 6; ++i) {
    if (axes_[i].kind == TransformAxisTerm::Kind::kConstant && axes_[i].value == 0.0) continue;
    X.p += CalcAxisValue(i, q) * axes_[i].axis;
  }
  return X;
}

Mat6X CustomJointModel::CalcH_FM(std::span<const double> q) const {
  return constant_H_ ? constant_H_FM_ : EvaluateH_FM(q);
}

Mat6X CustomJointModel::EvaluateH_FM(std::span<const double> q) const {
  double J[6][6];
  CalcJ(q, J);
  Vec3 e[3];
  CalcRotationAxesInF(q, e);
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
  if (constant_H_) return constant_H_FM_ * Eigen::Map<const VecX>(u.data(), nq_);
  double J[6][6];
  CalcJ(q, J);
  Vec3 e[3];
  CalcRotationAxesInF(q, e);
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
  if (constant_H_) return SpatialVec::Zero();  // a Pin-like joint: H_FM does not change
  double J[6][6];
  CalcJ(q, J);
  Vec3 e[3];
  CalcRotationAxesInF(q, e);
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
  for (int i = 0; i < 3 && has_curved_axes_; ++i) {
    a_w += CalcSecondTerm(i, q, u) * e[i];
    a_v += CalcSecondTerm(i + 3, q, u) * axes_[i + 3].axis;
  }
  SpatialVec A;
  A << a_w, a_v;
  return A;
}

std::vector<std::pair<int, double>> CustomJointModel::Breakpoints() const {
  std::vector<std::pair<int, double>> points;
  for (const TransformAxisTerm& term : axes_) {
    if (term.kind != TransformAxisTerm::Kind::kFunction1) continue;
    for (const double x : term.function->Breakpoints()) points.emplace_back(term.args[0], x);
  }
  return points;
}

}  // namespace sinew::kinematics

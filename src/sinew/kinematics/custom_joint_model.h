// The CustomJoint model (OpenSim SpatialTransform on Simbody's FunctionBased mobilizer), also
// used for every joint that is a special case of it: Pin, Slider, Universal, Gimbal, Planar.
#pragma once

#include <sinew/kinematics/joint_model.h>

#include <array>
#include <vector>

namespace sinew::kinematics {

/// One of the six axes of a CustomJoint: s = f(q[args...]) along or about `axis` (unit, in F).
struct TransformAxisTerm {
  /// How s is computed: a constant, s = q[arg], s = slope q[arg] + value, a one-argument or a
  /// multi-argument function. CustomJointModel turns a kFunction1 whose function is a
  /// LinearFunction into kIdentity or kAffine (the same values without a virtual call).
  enum class Kind { kConstant, kIdentity, kAffine, kFunction1, kFunctionN };
  Kind kind = Kind::kConstant;
  Vec3 axis = Vec3::UnitX();  ///< Unit axis in F.
  double value = 0.0;         ///< For kConstant; the intercept for kAffine.
  double slope = 1.0;         ///< For kAffine.
  std::vector<int> args;  ///< Joint-local coordinate indices (kIdentity/kAffine/kFunction1: one).
  functions::FunctionPtr function;  ///< For kFunction1 / kFunctionN (kept for reports otherwise).
};

/// X_FM(q) = [R(a1,s1) R(a2,s2) R(a3,s3), s4 a4 + s5 a5 + s6 a6] with s_i = f_i(q): rotations
/// form a body-fixed sequence with axes given in F; the translation is in F and not rotated.
/// Speeds are u = qdot.
class CustomJointModel final : public JointModel {
 public:
  /// `axes` are rotation1..3 then translation1..3; `nq` is the number of joint coordinates.
  CustomJointModel(std::array<TransformAxisTerm, 6> axes, int nq);

  int nq() const override { return nq_; }
  Transform CalcX_FM(std::span<const double> q) const override;
  Mat6X CalcH_FM(std::span<const double> q) const override;
  void CalcQDot(std::span<const double> q, std::span<const double> u,
                std::span<double> qdot) const override;
  bool QDotIsU() const override { return true; }
  void CalcU(std::span<const double> q, std::span<const double> qdot,
             std::span<double> u) const override;
  SpatialVec CalcHDotU(std::span<const double> q, std::span<const double> u) const override;
  SpatialVec CalcV_FM(std::span<const double> q, std::span<const double> u) const override;
  std::vector<std::pair<int, double>> Breakpoints() const override;

  /// The six axes (for reports and tests).
  const std::array<TransformAxisTerm, 6>& axes() const { return axes_; }

 private:
  // s_i for axis i alone.
  double CalcAxisValue(int i, std::span<const double> q) const;
  // ds_i/dq_k into J[i][k] (k < nq_), zeroed first.
  void CalcJ(std::span<const double> q, double (*J)[6]) const;
  // CalcJ from the axes' functions (CalcJ copies constant_J_ instead when no axis is curved).
  void EvaluateJ(std::span<const double> q, double (*J)[6]) const;
  // H_FM from J and the rotation axes (CalcH_FM returns constant_H_FM_ instead when constant).
  Mat6X EvaluateH_FM(std::span<const double> q) const;
  // sum_{k,l} d2 s_i / dq_k dq_l u_k u_l.
  double CalcSecondTerm(int i, std::span<const double> q, std::span<const double> u) const;
  // The three rotation axes in F at q: a1, R1 a2, R1 R2 a3 (only s_1 and s_2 are evaluated).
  void CalcRotationAxesInF(std::span<const double> q, Vec3* e) const;

  // cos and sin of s_i for rotation axis i (0..2); precomputed for a constant axis.
  void CalcCosSin(int i, std::span<const double> q, double* c, double* s) const;
  // v <- R(a_i, s_i) v, given cos and sin of s_i.
  Vec3 RotateAbout(int i, double c, double s, const Vec3& v) const;
  // M <- M R(a_i, s_i), given cos and sin of s_i.
  void MultiplyByRotation(int i, double c, double s, Mat3& M) const;

  std::array<TransformAxisTerm, 6> axes_;
  int nq_;
  // Per rotation axis: 0, 1 or 2 when the axis is exactly +x, +y or +z of F (an elementary
  // rotation, applied to two columns only), -1 otherwise (Rodrigues' formula).
  std::array<int, 3> coordinate_axis_{};
  // Per rotation axis: constant zero (skipped), and cos/sin of a constant angle.
  std::array<bool, 3> rotation_zero_{};
  // Whether some axis has a second derivative (kFunction1 or kFunctionN); without one the
  // velocity-product terms have no second-derivative part.
  bool has_curved_axes_ = false;
  // Without curved axes and with at most one rotation axis that moves, H_FM's columns are
  // constant in F (the moving axis turns only about itself): Hdot u is exactly zero, and
  // CalcH_FM returns constant_H_FM_.
  bool constant_H_ = false;
  Mat6X constant_H_FM_;
  // Without curved axes ds_i/dq_k does not depend on q: CalcJ copies it from here.
  double constant_J_[6][6] = {};
  std::array<double, 3> fixed_cos_{}, fixed_sin_{};
};

}  // namespace sinew::kinematics

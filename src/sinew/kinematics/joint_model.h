// The kinematics of one OpenSim joint, as the engine and forward kinematics use it:
// the transform X_FM(q), the velocity map V_FM = H_FM(q) u, qdot = N(q) u, and the bias
// acceleration Hdot u. Frames: F is the joint frame on the parent, M the one on the child.
#pragma once

#include <sinew/math/transform.h>
#include <sinew/math/types.h>
#include <sinew/model/model_spec.h>

#include <memory>
#include <span>
#include <utility>
#include <vector>

namespace sinew::kinematics {

/// X_FM(q) and its derivatives for one joint. Coordinates q and speeds u are in the order of
/// JointSpec::coordinates. For most joints u = qdot; for BallJoint (and FreeJoint's rotation)
/// q are body-fixed X-Y-Z angles and u is the angular velocity w_FM expressed in F (and for
/// FreeJoint's translation, u is v_FM expressed in F). Spatial vectors are [angular; linear],
/// the linear part being the velocity of M's origin measured in F, expressed in F.
class JointModel {
 public:
  virtual ~JointModel() = default;

  /// Number of generalized coordinates and speeds (equal for every OpenSim joint).
  virtual int nq() const = 0;
  int nu() const { return nq(); }

  /// X_FM(q).
  virtual Transform CalcX_FM(std::span<const double> q) const = 0;
  /// The 6 x nu matrix H_FM(q) with V_FM_F = H_FM(q) * u (spatial velocity of M in F, in F).
  virtual Mat6X CalcH_FM(std::span<const double> q) const = 0;
  /// qdot = N(q) * u, written into `qdot` (nq entries).
  virtual void CalcQDot(std::span<const double> q, std::span<const double> u,
                        std::span<double> qdot) const = 0;
  /// True when qdot = u at every q (N is the identity, so Ndot u is zero): callers may skip
  /// CalcQDot. False is always safe.
  virtual bool QDotIsU() const { return false; }
  /// u from qdot (the inverse of CalcQDot), written into `u`.
  virtual void CalcU(std::span<const double> q, std::span<const double> qdot,
                     std::span<double> u) const = 0;
  /// The bias term Hdot(q, u) * u of the spatial acceleration A_FM_F = H * udot + Hdot * u.
  virtual SpatialVec CalcHDotU(std::span<const double> q, std::span<const double> u) const = 0;
  /// V_FM_F = H_FM(q) * u. Joint models override it to avoid allocating H (forward
  /// kinematics calls it per joint and pose); the default forms H.
  virtual SpatialVec CalcV_FM(std::span<const double> q, std::span<const double> u) const {
    if (nq() == 0) return SpatialVec::Zero();
    return CalcH_FM(q) * Eigen::Map<const VecX>(u.data(), nq());
  }

  /// The values of the joint's coordinates (index in q, value) where the second or third
  /// derivative of X_FM(q) jumps (functions::Function::Breakpoints of an axis function of one
  /// coordinate): there the velocity-product terms, and so the accelerations or their rate of
  /// change, jump.
  virtual std::vector<std::pair<int, double>> Breakpoints() const { return {}; }
};

/// True when MakeJointModel can model joints of this type: every JointType except
/// kConstantCurvature and kUnknown. The engine builds the same set (it uses these models).
bool IsJointTypeModeled(model::JointType kind);

/// Builds the JointModel of `spec.joints[joint_index]` (a type IsJointTypeModeled accepts).
/// Throws sinew::Error for a joint it cannot model.
std::unique_ptr<JointModel> MakeJointModel(const model::ModelSpec& spec, int joint_index);

}  // namespace sinew::kinematics

// Joints whose rotational coordinates are body-fixed X-Y-Z angles but whose speeds are the
// angular velocity w_FM expressed in F (OpenSim runs Simbody in Euler-angle mode): BallJoint,
// FreeJoint and EllipsoidJoint. Also WeldJoint (no motion).
#pragma once

#include <sinew/kinematics/joint_model.h>

namespace sinew::kinematics {

/// BallJoint: q = body-fixed X-Y-Z angles of R_FM (rad), u = w_FM in F (rad/s), p_FM = 0.
class BallJointModel final : public JointModel {
 public:
  SpatialVec CalcV_FM(std::span<const double>, std::span<const double> u) const override {
    SpatialVec V;
    V << u[0], u[1], u[2], 0, 0, 0;
    return V;
  }
  int nq() const override { return 3; }
  Transform CalcX_FM(std::span<const double> q) const override;
  Mat6X CalcH_FM(std::span<const double> q) const override;
  void CalcQDot(std::span<const double> q, std::span<const double> u,
                std::span<double> qdot) const override;
  void CalcU(std::span<const double> q, std::span<const double> qdot,
             std::span<double> u) const override;
  SpatialVec CalcHDotU(std::span<const double> q, std::span<const double> u) const override;
};

/// FreeJoint: q = [3 body-fixed X-Y-Z angles (rad); p_FM in F (m)], u = [w_FM in F; v_FM in F].
class FreeJointModel final : public JointModel {
 public:
  SpatialVec CalcV_FM(std::span<const double>, std::span<const double> u) const override {
    SpatialVec V;
    V << u[0], u[1], u[2], u[3], u[4], u[5];
    return V;
  }
  int nq() const override { return 6; }
  Transform CalcX_FM(std::span<const double> q) const override;
  Mat6X CalcH_FM(std::span<const double> q) const override;
  void CalcQDot(std::span<const double> q, std::span<const double> u,
                std::span<double> qdot) const override;
  void CalcU(std::span<const double> q, std::span<const double> qdot,
             std::span<double> u) const override;
  SpatialVec CalcHDotU(std::span<const double> q, std::span<const double> u) const override;
};

/// EllipsoidJoint (Simbody's Ellipsoid mobilizer): R_FM from body-fixed X-Y-Z angles q, and
/// p_FM = [rx nx, ry ny, rz nz] where n = R_FM z is M's z axis in F, so M's origin stays on the
/// ellipsoid with radii r centred at F's origin. u = w_FM in F.
class EllipsoidJointModel final : public JointModel {
 public:
  /// `radii` are the ellipsoid semi-axes along F's x, y, z (m).
  explicit EllipsoidJointModel(const Vec3& radii) : radii_(radii) {}
  int nq() const override { return 3; }
  Transform CalcX_FM(std::span<const double> q) const override;
  Mat6X CalcH_FM(std::span<const double> q) const override;
  void CalcQDot(std::span<const double> q, std::span<const double> u,
                std::span<double> qdot) const override;
  void CalcU(std::span<const double> q, std::span<const double> qdot,
             std::span<double> u) const override;
  SpatialVec CalcHDotU(std::span<const double> q, std::span<const double> u) const override;
  SpatialVec CalcV_FM(std::span<const double> q, std::span<const double> u) const override;

  const Vec3& radii() const { return radii_; }

 private:
  Vec3 radii_;
};

/// WeldJoint: X_FM = identity, no coordinates.
class WeldJointModel final : public JointModel {
 public:
  int nq() const override { return 0; }
  Transform CalcX_FM(std::span<const double>) const override { return Transform(); }
  Mat6X CalcH_FM(std::span<const double>) const override { return Mat6X(6, 0); }
  void CalcQDot(std::span<const double>, std::span<const double>,
                std::span<double>) const override {}
  bool QDotIsU() const override { return true; }
  void CalcU(std::span<const double>, std::span<const double>, std::span<double>) const override {}
  SpatialVec CalcHDotU(std::span<const double>, std::span<const double>) const override {
    return SpatialVec::Zero();
  }
};

}  // namespace sinew::kinematics

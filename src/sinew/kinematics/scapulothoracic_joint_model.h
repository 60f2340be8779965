// OpenSim's ScapulothoracicJoint, reproduced from its Simbody construction:
// parent frame F -> (rotated by +90 deg about z) Ellipsoid mobilizer with radii (ry, rx, rz)
// -> massless body -> Pin about the winging axis -> massless body -> weld to the child frame M.
#pragma once

#include <sinew/kinematics/joint_model.h>

namespace sinew::kinematics {

/// ScapulothoracicJoint. q = [abduction, elevation, upward rotation, winging] (rad).
/// X_FM(q) = Rz(pi/2) * E(q0, q1, q2) * Rz(-pi/2) * W(q3), where E is the Ellipsoid mobilizer
/// transform with radii (ry, rx, rz) (the thorax radii swapped into the rotated frame) and W is
/// a rotation by q3 about the unit winging axis d = (-sin(dir), cos(dir), 0) through the point
/// o = (ox, oy, 0). Speeds: u0..2 = the ellipsoid mobilizer's angular velocity expressed in its
/// own F frame (F rotated by +90 deg about z), u3 = q3dot.
class ScapulothoracicJointModel final : public JointModel {
 public:
  /// `radii`: thoracic_ellipsoid_radii_x_y_z (m, in F); `origin`: scapula_winging_axis_origin
  /// (m); `direction`: scapula_winging_axis_direction (rad).
  ScapulothoracicJointModel(const Vec3& radii, double origin_x, double origin_y, double direction);

  int nq() const override { return 4; }
  Transform CalcX_FM(std::span<const double> q) const override;
  Mat6X CalcH_FM(std::span<const double> q) const override;
  void CalcQDot(std::span<const double> q, std::span<const double> u,
                std::span<double> qdot) const override;
  void CalcU(std::span<const double> q, std::span<const double> qdot,
             std::span<double> u) const override;
  SpatialVec CalcHDotU(std::span<const double> q, std::span<const double> u) const override;

 private:
  // Ellipsoid part in F0: R_E, p_E, n; winging part in the ellipsoid's M0 frame: R_C, p_C, m
  // (m = the winging-rotated origin, with p_C = Rz(-pi/2) o - m), w_C per unit u3.
  struct Parts {
    Mat3 R_E;
    Vec3 p_E, n;
    Mat3 R_C;
    Vec3 p_C, m, w_C;
  };
  Parts CalcParts(std::span<const double> q) const;

  Vec3 radii_;   // In the ellipsoid mobilizer's frame: (ry, rx, rz).
  Vec3 origin_;  // o in the pin's frame (massless body 1).
  Vec3 axis_;    // d in the same frame.
  Mat3 R_FF0_;   // Rz(pi/2).
};

}  // namespace sinew::kinematics

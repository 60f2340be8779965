// Cartesian equations between a frame F fixed on one body and a frame M fixed on another: the
// origins coincide, and optionally some axes stay perpendicular. They impose the direct joint
// forms (Pin, Ball, Universal, Weld) and OpenSim's WeldConstraint and PointConstraint.
#pragma once

#include <sinew/engine/constraint.h>
#include <sinew/math/transform.h>

#include <array>
#include <string>
#include <vector>

namespace sinew::engine {

/// Which relative motions of M in F the equations take away.
enum class FrameConstraintKind {
  kPoint,      ///< 3 rows: the origins coincide (a ball joint, OpenSim's PointConstraint)
  kPin,        ///< 5 rows: and z_M stays along z_F
  kUniversal,  ///< 4 rows: and y_M stays perpendicular to x_F
  kWeld,       ///< 6 rows: and the axes stay aligned (x_F.y_M = y_F.z_M = z_F.x_M = 0)
};

/// phi = [p_GMo - p_GFo; a_i . b_i] with a_i an axis of F and b_i an axis of M (rows in G).
/// Like Simbody's Weld, the three dot products also vanish at a half turn about an axis; the
/// tree placement (joints) or assembly from nearby defaults (extra constraints) picks the
/// aligned branch.
class FrameConstraint final : public Constraint {
 public:
  /// F = X_PF in body `body_f` (P), M = X_BM in body `body_m` (B); body 0 is ground.
  FrameConstraint(std::string name, int body_f, const Transform& X_PF, int body_m,
                  const Transform& X_BM, FrameConstraintKind kind);

  std::string name() const override { return name_; }
  int NumEquations() const override { return 3 + static_cast<int>(pairs_.size()); }
  std::vector<int> Bodies() const override { return {body_f_, body_m_}; }
  void CalcPositionError(const System& system, const State& state,
                         Eigen::Ref<VecX> phi) const override;
  void CalcJacobian(const System& system, const State& state, Eigen::Ref<MatX> J) const override;
  void CalcAccelerationRhs(const System& system, const State& state,
                           Eigen::Ref<VecX> b) const override;

 private:
  std::string name_;
  int body_f_, body_m_;
  Transform X_PF_, X_BM_;
  std::vector<std::array<int, 2>> pairs_;  ///< (axis of F, axis of M) kept perpendicular
};

}  // namespace sinew::engine

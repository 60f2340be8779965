// OpenSim's ConstantDistanceConstraint (Simbody's Constraint::Rod): two points fixed on two
// bodies stay a given distance apart.
#pragma once

#include <sinew/engine/constraint.h>
#include <sinew/math/types.h>

#include <string>
#include <vector>

namespace sinew::forces {

/// One equation phi = (|r|^2 - d^2) / (2 d) = 0 with r = p_GQ2 - p_GQ1 (Q1 fixed on body 1, Q2
/// on body 2) and d = constant_distance: it has units of length, equals |r| - d to first order,
/// and stays smooth where r = 0. Its multiplier is the rod's compression force divided by |r|/d.
class ConstantDistanceConstraint final : public engine::Constraint {
 public:
  /// Engine body indices (0 is ground) and the points in their bodies' frames (m). Throws
  /// sinew::Error (component `name`) unless d > 0 and the bodies differ.
  ConstantDistanceConstraint(std::string name, int body1, const Vec3& p_B1Q1, int body2,
                             const Vec3& p_B2Q2, double distance);

  std::string name() const override { return name_; }

  int NumEquations() const override { return 1; }
  std::vector<int> Bodies() const override { return {body1_, body2_}; }
  void CalcPositionError(const engine::System& system, const engine::State& state,
                         Eigen::Ref<VecX> phi) const override;
  void CalcJacobian(const engine::System& system, const engine::State& state,
                    Eigen::Ref<MatX> J) const override;
  void CalcAccelerationRhs(const engine::System& system, const engine::State& state,
                           Eigen::Ref<VecX> b) const override;

 private:
  struct Geometry {
    Vec3 r1, r2;  ///< arms p_GQi - p_GBio
    Vec3 r;       ///< p_GQ2 - p_GQ1
  };
  Geometry CalcGeometry(const engine::State& state) const;

  std::string name_;
  int body1_, body2_;
  Vec3 p_B1Q1_, p_B2Q2_;
  double distance_;
};

}  // namespace sinew::forces

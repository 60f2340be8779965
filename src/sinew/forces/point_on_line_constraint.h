// OpenSim's PointOnLineConstraint (Simbody's Constraint::PointOnLine): a point fixed on a
// follower body stays on a line fixed in a line body.
#pragma once

#include <sinew/engine/constraint.h>
#include <sinew/math/types.h>

#include <string>
#include <vector>

namespace sinew::forces {

/// Two equations phi_k = n_k . (p_GQ - p_GL) = 0, where L (point_on_line) and the unit line
/// direction d are fixed in the line body, Q (point_on_follower) is fixed in the follower body,
/// and n_1, n_2 are unit vectors fixed in the line body, perpendicular to d and to each other.
/// The follower may slide along the line and turn freely.
class PointOnLineConstraint final : public engine::Constraint {
 public:
  /// `line_body` and `follower_body` are engine body indices (0 is ground); `direction` (in
  /// the line body's frame) is normalized. Throws sinew::Error (component `name`) for a zero
  /// direction or one body used twice.
  PointOnLineConstraint(std::string name, int line_body, const Vec3& direction, const Vec3& p_LL,
                        int follower_body, const Vec3& p_FQ);

  std::string name() const override { return name_; }

  int NumEquations() const override { return 2; }
  /// The line body, then the follower body.
  std::vector<int> Bodies() const override { return {line_body_, follower_body_}; }
  void CalcPositionError(const engine::System& system, const engine::State& state,
                         Eigen::Ref<VecX> phi) const override;
  void CalcJacobian(const engine::System& system, const engine::State& state,
                    Eigen::Ref<MatX> J) const override;
  void CalcAccelerationRhs(const engine::System& system, const engine::State& state,
                           Eigen::Ref<VecX> b) const override;

 private:
  struct Geometry;
  Geometry CalcGeometry(const engine::State& state) const;

  std::string name_;
  int line_body_, follower_body_;
  Mat3 normals_L_;  ///< columns n_1, n_2, d in the line body's frame
  Vec3 p_LL_;       ///< the point on the line, in the line body's frame
  Vec3 p_FQ_;       ///< the follower's point, in the follower body's frame
};

}  // namespace sinew::forces

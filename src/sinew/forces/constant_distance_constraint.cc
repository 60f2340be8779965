#include <sinew/common/error.h>
#include <sinew/engine/pose.h>
#include <sinew/engine/state.h>
#include <sinew/forces/constant_distance_constraint.h>

#include <cmath>
#include <utility>

namespace sinew::forces {

ConstantDistanceConstraint::ConstantDistanceConstraint(std::string name, int body1,
                                                       const Vec3& p_B1Q1, int body2,
                                                       const Vec3& p_B2Q2, double distance)
    : name_(std::move(name)),
      body1_(body1),
      body2_(body2),
      p_B1Q1_(p_B1Q1),
      p_B2Q2_(p_B2Q2),
      distance_(distance) {
  if (!(distance > 0.0) || !std::isfinite(distance)) {
    throw Error(
        SourceLocation{}, name_,
        "constant_distance must be a finite length > 0 (it is " + std::to_string(distance) + ")");
  }
  if (body1 == body2) throw Error(SourceLocation{}, name_, "body_1 and body_2 are the same body");
}

ConstantDistanceConstraint::Geometry ConstantDistanceConstraint::CalcGeometry(
    const engine::State& state) const {
  const Transform X_GB1 = engine::PoseOf(state.bodies[body1_]);
  const Transform X_GB2 = engine::PoseOf(state.bodies[body2_]);
  Geometry g;
  g.r1 = X_GB1.R * p_B1Q1_;
  g.r2 = X_GB2.R * p_B2Q2_;
  g.r = (X_GB2.p + g.r2) - (X_GB1.p + g.r1);
  return g;
}

void ConstantDistanceConstraint::CalcPositionError(const engine::System&,
                                                   const engine::State& state,
                                                   Eigen::Ref<VecX> phi) const {
  const Geometry g = CalcGeometry(state);
  phi[0] = (g.r.squaredNorm() - distance_ * distance_) / (2.0 * distance_);
}

void ConstantDistanceConstraint::CalcJacobian(const engine::System&, const engine::State& state,
                                              Eigen::Ref<MatX> J) const {
  // phi' = r . (v_Q2 - v_Q1) / d with v_Qi = v_Bi + w_Bi x r_i.
  const Geometry g = CalcGeometry(state);
  J.block<1, 3>(0, 0) = -g.r1.cross(g.r).transpose() / distance_;
  J.block<1, 3>(0, 3) = -g.r.transpose() / distance_;
  J.block<1, 3>(0, 6) = g.r2.cross(g.r).transpose() / distance_;
  J.block<1, 3>(0, 9) = g.r.transpose() / distance_;
}

void ConstantDistanceConstraint::CalcAccelerationRhs(const engine::System&,
                                                     const engine::State& state,
                                                     Eigen::Ref<VecX> b) const {
  // phi'' = J vdot + (|r'|^2 + r . (w2 x (w2 x r2) - w1 x (w1 x r1))) / d.
  const Geometry g = CalcGeometry(state);
  const engine::BodyState& B1 = state.bodies[body1_];
  const engine::BodyState& B2 = state.bodies[body2_];
  const Vec3 r_dot = (B2.v_GB + B2.w_GB.cross(g.r2)) - (B1.v_GB + B1.w_GB.cross(g.r1));
  const Vec3 centripetal = B2.w_GB.cross(B2.w_GB.cross(g.r2)) - B1.w_GB.cross(B1.w_GB.cross(g.r1));
  b[0] = -(r_dot.squaredNorm() + g.r.dot(centripetal)) / distance_;
}

}  // namespace sinew::forces

#include <sinew/common/error.h>
#include <sinew/engine/pose.h>
#include <sinew/engine/state.h>
#include <sinew/forces/point_on_line_constraint.h>

#include <cmath>
#include <utility>

namespace sinew::forces {

// Everything the three levels use, in G: the normals, the arms from the bodies' origins and
// the gap r = p_GQ - p_GL.
struct PointOnLineConstraint::Geometry {
  Vec3 n[2];
  Vec3 r_LoL;  ///< p_GL - p_GLo (line body origin Lo)
  Vec3 r_FoQ;  ///< p_GQ - p_GFo
  Vec3 r;      ///< p_GQ - p_GL
};

PointOnLineConstraint::PointOnLineConstraint(std::string name, int line_body, const Vec3& direction,
                                             const Vec3& p_LL, int follower_body, const Vec3& p_FQ)
    : name_(std::move(name)),
      line_body_(line_body),
      follower_body_(follower_body),
      p_LL_(p_LL),
      p_FQ_(p_FQ) {
  if (!(direction.norm() > 0.0)) throw Error(SourceLocation{}, name_, "line_direction_vec is zero");
  if (line_body == follower_body) {
    throw Error(SourceLocation{}, name_, "the line body and the follower body are the same body");
  }
  // Two unit normals of d: any perpendicular pair fixes the same two equations.
  const Vec3 d = direction.normalized();
  const Vec3 helper = std::abs(d.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 n1 = d.cross(helper).normalized();
  normals_L_.col(0) = n1;
  normals_L_.col(1) = d.cross(n1);
  normals_L_.col(2) = d;
}

PointOnLineConstraint::Geometry PointOnLineConstraint::CalcGeometry(
    const engine::State& state) const {
  const Transform X_GL = engine::PoseOf(state.bodies[line_body_]);
  const Transform X_GF = engine::PoseOf(state.bodies[follower_body_]);
  Geometry g;
  g.n[0] = X_GL.R * normals_L_.col(0);
  g.n[1] = X_GL.R * normals_L_.col(1);
  g.r_LoL = X_GL.R * p_LL_;
  g.r_FoQ = X_GF.R * p_FQ_;
  g.r = (X_GF.p + g.r_FoQ) - (X_GL.p + g.r_LoL);
  return g;
}

void PointOnLineConstraint::CalcPositionError(const engine::System&, const engine::State& state,
                                              Eigen::Ref<VecX> phi) const {
  const Geometry g = CalcGeometry(state);
  for (int k = 0; k < 2; ++k) phi[k] = g.n[k].dot(g.r);
}

void PointOnLineConstraint::CalcJacobian(const engine::System&, const engine::State& state,
                                         Eigen::Ref<MatX> J) const {
  // d/dt (n . r) = (w_L x n) . r + n . (v_Q - v_L): the line body turns n and moves L.
  const Geometry g = CalcGeometry(state);
  for (int k = 0; k < 2; ++k) {
    const Vec3& n = g.n[k];
    J.block<1, 3>(k, 0) = n.cross(g.r + g.r_LoL).transpose();
    J.block<1, 3>(k, 3) = -n.transpose();
    J.block<1, 3>(k, 6) = g.r_FoQ.cross(n).transpose();
    J.block<1, 3>(k, 9) = n.transpose();
  }
}

void PointOnLineConstraint::CalcAccelerationRhs(const engine::System&, const engine::State& state,
                                                Eigen::Ref<VecX> b) const {
  // phi'' = J vdot + 2 (w_L x n) . r' + n . (w_F x (w_F x r_FoQ) - w_L x (w_L x r_LoL))
  //         + (w_L x (w_L x n)) . r, with r' = v_Q - v_L; b is minus the velocity terms.
  const Geometry g = CalcGeometry(state);
  const engine::BodyState& L = state.bodies[line_body_];
  const engine::BodyState& F = state.bodies[follower_body_];
  const Vec3 v_Q = F.v_GB + F.w_GB.cross(g.r_FoQ);
  const Vec3 v_L = L.v_GB + L.w_GB.cross(g.r_LoL);
  const Vec3 r_dot = v_Q - v_L;
  const Vec3 centripetal =
      F.w_GB.cross(F.w_GB.cross(g.r_FoQ)) - L.w_GB.cross(L.w_GB.cross(g.r_LoL));
  for (int k = 0; k < 2; ++k) {
    const Vec3 n_dot = L.w_GB.cross(g.n[k]);
    b[k] = -(2.0 * n_dot.dot(r_dot) + g.n[k].dot(centripetal) + L.w_GB.cross(n_dot).dot(g.r));
  }
}

}  // namespace sinew::forces

#include <sinew/engine/frame_constraint.h>
#include <sinew/engine/pose.h>
#include <sinew/engine/state.h>

#include <utility>

namespace sinew::engine {
namespace {

// Frames F and M in G with their bodies' poses.
struct Frames {
  Transform X_GP, X_GB, X_GF, X_GM;
};

Frames CalcFrames(const State& state, int body_f, const Transform& X_PF, int body_m,
                  const Transform& X_BM) {
  Frames f;
  f.X_GP = PoseOf(state.bodies[body_f]);
  f.X_GB = PoseOf(state.bodies[body_m]);
  f.X_GF = f.X_GP * X_PF;
  f.X_GM = f.X_GB * X_BM;
  return f;
}

}  // namespace

FrameConstraint::FrameConstraint(std::string name, int body_f, const Transform& X_PF, int body_m,
                                 const Transform& X_BM, FrameConstraintKind kind)
    : name_(std::move(name)), body_f_(body_f), body_m_(body_m), X_PF_(X_PF), X_BM_(X_BM) {
  switch (kind) {
    case FrameConstraintKind::kPin:
      pairs_ = {{0, 2}, {1, 2}};
      break;
    case FrameConstraintKind::kUniversal:
      pairs_ = {{0, 1}};
      break;
    case FrameConstraintKind::kWeld:
      pairs_ = {{0, 1}, {1, 2}, {2, 0}};
      break;
    case FrameConstraintKind::kPoint:
      break;
  }
}

void FrameConstraint::CalcPositionError(const System&, const State& state,
                                        Eigen::Ref<VecX> phi) const {
  const Frames f = CalcFrames(state, body_f_, X_PF_, body_m_, X_BM_);
  phi.head<3>() = f.X_GM.p - f.X_GF.p;
  for (size_t k = 0; k < pairs_.size(); ++k) {
    phi[3 + k] = f.X_GF.R.col(pairs_[k][0]).dot(f.X_GM.R.col(pairs_[k][1]));
  }
}

void FrameConstraint::CalcJacobian(const System&, const State& state, Eigen::Ref<MatX> J) const {
  const Frames f = CalcFrames(state, body_f_, X_PF_, body_m_, X_BM_);
  const Vec3 r_PF = f.X_GF.p - f.X_GP.p;
  const Vec3 r_BM = f.X_GM.p - f.X_GB.p;
  J.setZero();
  J.block<3, 3>(0, 0) = Skew(r_PF);
  J.block<3, 3>(0, 3) = -Mat3::Identity();
  J.block<3, 3>(0, 6) = -Skew(r_BM);
  J.block<3, 3>(0, 9) = Mat3::Identity();
  for (size_t k = 0; k < pairs_.size(); ++k) {
    // d/dt (a . b) = (w_B - w_P) . (b x a)
    const Vec3 bxa = f.X_GM.R.col(pairs_[k][1]).cross(f.X_GF.R.col(pairs_[k][0]));
    J.block<1, 3>(3 + k, 0) = -bxa.transpose();
    J.block<1, 3>(3 + k, 6) = bxa.transpose();
  }
}

void FrameConstraint::CalcAccelerationRhs(const System&, const State& state,
                                          Eigen::Ref<VecX> b) const {
  const Frames f = CalcFrames(state, body_f_, X_PF_, body_m_, X_BM_);
  const BodyState& P = state.bodies[body_f_];
  const BodyState& B = state.bodies[body_m_];
  const Vec3 r_PF = f.X_GF.p - f.X_GP.p;
  const Vec3 r_BM = f.X_GM.p - f.X_GB.p;
  b.head<3>() = P.w_GB.cross(P.w_GB.cross(r_PF)) - B.w_GB.cross(B.w_GB.cross(r_BM));
  const Vec3 w_rel = B.w_GB - P.w_GB;
  for (size_t k = 0; k < pairs_.size(); ++k) {
    const Vec3 a = f.X_GF.R.col(pairs_[k][0]);
    const Vec3 bb = f.X_GM.R.col(pairs_[k][1]);
    b[3 + k] = -w_rel.dot(B.w_GB.cross(bb).cross(a) + bb.cross(P.w_GB.cross(a)));
  }
}

}  // namespace sinew::engine

#include <sinew/engine/loads.h>
#include <sinew/engine/pose.h>
#include <sinew/engine/state.h>
#include <sinew/forces/two_frame_linker.h>
#include <sinew/math/rotation.h>

namespace sinew::forces {

engine::ForceSupport SupportOfBodies(int body1, int body2) {
  engine::ForceSupport support;
  if (body1 != 0) support.bodies.push_back(body1);
  if (body2 != 0 && body2 != body1) support.bodies.push_back(body2);
  return support;
}

FrameDeflection CalcFrameDeflection(const engine::State& state, const LinkedFrames& frames) {
  const engine::BodyState& b1 = state.bodies[frames.body1];
  const engine::BodyState& b2 = state.bodies[frames.body2];
  FrameDeflection d;
  d.X_GF = engine::PoseOf(b1) * frames.X_B1F;
  d.X_GM = engine::PoseOf(b2) * frames.X_B2M;
  const Transform X_FM = d.X_GF.Inverse() * d.X_GM;
  const Vec3 angles = BodyFixedXYZFromRotation(X_FM.R);
  d.q << angles, X_FM.p;

  // Velocities of the frames' origins, then M's motion in F with the derivative taken in F.
  const Vec3 v_GFo = engine::PointVelocity(b1, d.X_GF.p);
  const Vec3 v_GMo = engine::PointVelocity(b2, d.X_GM.p);
  const Vec3 p_FoMo_G = d.X_GM.p - d.X_GF.p;
  const Mat3 R_FG = d.X_GF.R.transpose();
  const Vec3 w_FM_F = R_FG * (b2.w_GB - b1.w_GB);
  const Vec3 v_FMo_F = R_FG * (v_GMo - v_GFo - b1.w_GB.cross(p_FoMo_G));
  const Vec3 w_FM_M = X_FM.R.transpose() * w_FM_F;
  d.qdot << BodyFixedXYZRatesFromAngularVelocity(angles) * w_FM_M, v_FMo_F;
  return d;
}

void AddInternalForce(const engine::State& state, const LinkedFrames& frames,
                      const FrameDeflection& deflection, const Vec6& f, engine::Loads& loads) {
  const Vec3 angles = deflection.q.head<3>();
  const Vec3 m_M = BodyFixedXYZRatesFromAngularVelocity(angles).transpose() * f.head<3>();
  const Vec3 m_G = deflection.X_GM.R * m_M;
  const Vec3 f_G = deflection.X_GF.R * f.tail<3>();
  // Both forces act at Mo; body1's is given at the material point of body1 there.
  const Vec3 p_GMo = deflection.X_GM.p;
  const Vec3 p_B1Mo = engine::PoseOf(state.bodies[frames.body1]).Inverse() * p_GMo;
  loads.AddForceAtPoint(state, frames.body2, frames.X_B2M.p, f_G);
  loads.AddTorque(frames.body2, m_G);
  loads.AddForceAtPoint(state, frames.body1, p_B1Mo, -f_G);
  loads.AddTorque(frames.body1, -m_G);
}

}  // namespace sinew::forces

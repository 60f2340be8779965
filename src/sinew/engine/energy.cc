#include <sinew/engine/energy.h>

namespace sinew::engine {

double CalcKineticEnergy(const System& system, const State& state) {
  double T = 0.0;
  for (int b = 1; b < system.num_bodies(); ++b) {
    const Body& body = system.bodies()[b];
    const BodyState& s = state.bodies[b];
    const Mat3 R = s.quat_GB.normalized().toRotationMatrix();
    const Vec3 v_Cm = s.v_GB + s.w_GB.cross(R * body.p_BCm);
    const Vec3 w_B = R.transpose() * s.w_GB;
    T += 0.5 * body.mass * v_Cm.squaredNorm() + 0.5 * w_B.dot(body.I_Bcm_B * w_B);
  }
  return T;
}

double CalcGravityPotentialEnergy(const System& system, const State& state) {
  double V = 0.0;
  for (int b = 1; b < system.num_bodies(); ++b) {
    const Body& body = system.bodies()[b];
    const BodyState& s = state.bodies[b];
    const Vec3 p_GCm = s.p_GB + s.quat_GB.normalized() * body.p_BCm;
    V -= body.mass * system.gravity().dot(p_GCm);
  }
  return V;
}

double CalcMechanicalEnergy(const System& system, const State& state) {
  return CalcKineticEnergy(system, state) + CalcGravityPotentialEnergy(system, state);
}

}  // namespace sinew::engine

#include <sinew/engine/energy.h>
#include <sinew/engine/loads.h>

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

double CalcForcePotentialEnergy(const System& system, const State& state) {
  double V = 0.0;
  const auto& forces = system.force_elements();
  for (size_t k = 0; k < forces.size(); ++k) {
    V += forces[k]->CalcPotentialEnergy(system.MakeForceContext(static_cast<int>(k), state));
  }
  return V;
}

double CalcMechanicalEnergy(const System& system, const State& state) {
  return CalcKineticEnergy(system, state) + CalcGravityPotentialEnergy(system, state) +
         CalcForcePotentialEnergy(system, state);
}

double CalcForcePower(const System& system, const State& state, int k) {
  Loads loads(system.num_bodies(), system.num_coordinates());
  system.force_elements()[k]->AddLoads(system.MakeForceContext(k, state), loads);
  double P = 0.0;
  for (int b = 1; b < system.num_bodies(); ++b) {
    const BodyState& s = state.bodies[b];
    P += loads.body[b].head<3>().dot(s.w_GB) + loads.body[b].tail<3>().dot(s.v_GB);
  }
  // Every coordinate's speed is current (direct joints' are read off the poses), so the
  // generalized forces' power is the same whichever form the joint has.
  return P + loads.mobility.dot(state.u);
}

}  // namespace sinew::engine

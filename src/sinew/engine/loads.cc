#include <sinew/engine/loads.h>
#include <sinew/engine/pose.h>
#include <sinew/engine/state.h>

namespace sinew::engine {

Loads::Loads(int num_bodies, int num_coordinates)
    : body(num_bodies, SpatialVec::Zero()), mobility(VecX::Zero(num_coordinates)) {}

void Loads::AddForceAtPoint(const State& state, int b, const Vec3& p_BQ, const Vec3& f_G) {
  const BodyState& s = state.bodies[b];
  const Vec3 r_G = s.quat_GB.normalized() * p_BQ;  // from Bo to Q, in G
  body[b].head<3>() += r_G.cross(f_G);
  body[b].tail<3>() += f_G;
}

void Loads::AddForceAtOrigin(int b, const Vec3& f_G) { body[b].tail<3>() += f_G; }

void Loads::AddTorque(int b, const Vec3& tau_G) { body[b].head<3>() += tau_G; }

void Loads::AddTorqueBetween(int body_a, int body_b, const Vec3& tau_G) {
  body[body_b].head<3>() += tau_G;
  body[body_a].head<3>() -= tau_G;
}

void Loads::AddGeneralizedForce(int coordinate, double f) { mobility[coordinate] += f; }

void Loads::SetZero() {
  for (SpatialVec& f : body) f.setZero();
  mobility.setZero();
}

}  // namespace sinew::engine

// Applied loads: forces and torques on bodies, generalized forces on coordinates. Force
// elements (force_element.h) add to them.
#pragma once

#include <sinew/engine/force_element.h>
#include <sinew/math/types.h>

#include <vector>

namespace sinew::engine {

class System;
struct State;

/// Loads accumulated for one evaluation of the equations of motion. Body loads are kept as a
/// torque about the body origin Bo and a force, both expressed in G.
class Loads {
 public:
  Loads() = default;
  /// Zero loads for `num_bodies` bodies and `num_coordinates` coordinates.
  Loads(int num_bodies, int num_coordinates);

  /// Force `f_G` (N, in G) at the point of body `body` given in B as `p_BQ` (m). Needs the
  /// body's current pose from `state`.
  void AddForceAtPoint(const State& state, int body, const Vec3& p_BQ, const Vec3& f_G);
  /// Force `f_G` (N, in G) through the body origin Bo.
  void AddForceAtOrigin(int body, const Vec3& f_G);
  /// Torque `tau_G` (N m, in G) on body `body`.
  void AddTorque(int body, const Vec3& tau_G);
  /// Torque `tau_G` (N m, in G) on body `body_b` and its reaction -tau_G on `body_a`.
  void AddTorqueBetween(int body_a, int body_b, const Vec3& tau_G);
  /// Generalized force (N m for rotational, N for translational) on coordinate `coordinate`.
  void AddGeneralizedForce(int coordinate, double f);

  /// Sets everything to zero.
  void SetZero();

  /// Per body: [torque about Bo; force], expressed in G.
  std::vector<SpatialVec> body;
  /// Per coordinate: generalized force.
  VecX mobility;
};

}  // namespace sinew::engine

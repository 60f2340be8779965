// The geometry OpenSim's TwoFrameLinker forces share (BushingForce, FunctionBasedBushingForce,
// ExpressionBasedBushingForce): the deflection of a frame M (on body 2) from a frame F (on
// body 1) as six numbers, its rate, and internal forces in that basis applied to both bodies.
#pragma once

#include <sinew/engine/force_element.h>
#include <sinew/math/transform.h>
#include <sinew/math/types.h>

namespace sinew::engine {
struct State;
class Loads;
}  // namespace sinew::engine

namespace sinew::forces {

/// The support of a force between two bodies: both, ground (0) left out, once if the same.
engine::ForceSupport SupportOfBodies(int body1, int body2);

/// Two frames fixed to bodies: F on body1 (X_B1F), M on body2 (X_B2M). Either body may be
/// ground (0).
struct LinkedFrames {
  int body1 = 0;
  Transform X_B1F;
  int body2 = 0;
  Transform X_B2M;

  /// The bodies a force between the frames acts on (ground left out).
  engine::ForceSupport Support() const { return SupportOfBodies(body1, body2); }
};

/// The deflection of M from F: q = [body-fixed X-Y-Z angles of R_FM; p_FM expressed in F]
/// (OpenSim's computeDeflection), and its rate qdot = [N(angles) w_FM_M; the velocity of Mo in
/// F, differentiated in F] (computeDeflectionRate).
struct FrameDeflection {
  Transform X_GF, X_GM;
  Vec6 q = Vec6::Zero();
  Vec6 qdot = Vec6::Zero();
};

/// The deflection and its rate for the state's body poses and velocities.
FrameDeflection CalcFrameDeflection(const engine::State& state, const LinkedFrames& frames);

/// Applies the internal force f (in the basis of q: three generalized moments on the angles,
/// then a force on Mo expressed in F) to body2, and its reaction to body1, as OpenSim's
/// TwoFrameLinker::convertInternalForceToForcesOnFrames does: body2 gets the moment
/// R_GM N^T f_angles and the force R_GF f_force at Mo; body1 gets the opposite force at Mo
/// (equal and opposite loads: the power f . qdot).
void AddInternalForce(const engine::State& state, const LinkedFrames& frames,
                      const FrameDeflection& deflection, const Vec6& f, engine::Loads& loads);

}  // namespace sinew::forces

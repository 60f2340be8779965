// Building and changing a State: the default state, placing bodies from joint coordinates, and
// reading coordinates back from body poses.
#pragma once

#include <sinew/engine/state.h>
#include <sinew/engine/system.h>

#include <string_view>

namespace sinew::engine {

/// The state at time `t` with every coordinate at its default value and speed (prescribed
/// coordinates at f(t), f'(t)); bodies placed and moving accordingly, then assembled onto the
/// constraints when there are loops or extra constraints (AssembleState: free coordinates
/// moved as little as possible from their defaults, as OpenSim assembles); state variables at
/// their
/// elements' defaults, then initialized (InitializeStateVariables); inputs zero.
State MakeDefaultState(const System& system, double t = 0.0);

/// Gives every force element the chance to set its auxiliary state variables from the rest of
/// `state` (ForceElement::InitializeStateVariables, e.g. muscle equilibrium). MakeDefaultState
/// calls it; call it again after setting coordinates or loading states.
void InitializeStateVariables(const System& system, State& state);

/// Throws sinew::Error unless `state` has the sizes of `system` (bodies, coordinates, state
/// variables, inputs).
void CheckState(const System& system, const State& state);

/// Places every body (pose and twist) from the coordinates q and speeds u of `state`, walking
/// the tree from ground: X_GB = X_GP X_PF X_FM(q) inverse(X_BM), V_FM_F = H_FM(q) u.
void PlaceBodies(const System& system, State& state);

/// Reads the coordinates and speeds of the direct Cartesian joints off the body poses and
/// twists (angles unwrapped relative to the values held in `state`).
void UpdateDirectCoordinates(const System& system, State& state);

/// Coordinate value / speed by name (throws sinew::Error for an unknown name).
double GetCoordinateValue(const System& system, const State& state, std::string_view name);
double GetCoordinateSpeed(const System& system, const State& state, std::string_view name);
/// Sets a coordinate value / speed by name and re-places the bodies.
void SetCoordinateValue(const System& system, State& state, std::string_view name, double q);
void SetCoordinateSpeed(const System& system, State& state, std::string_view name, double u);

/// The spatial velocity of M in F, expressed in F, [w_FM_F; v_FM_F], of joint `j`.
SpatialVec CalcJointVelocity(const System& system, const State& state, int j);

/// X_FM of joint `j` read off the body poses of `state`.
Transform CalcJointTransform(const System& system, const State& state, int j);

/// The joint frames in G of a tree joint placed by PlaceBodyThroughJoint.
struct JointFrames {
  Transform X_GF, X_GM;
};
/// Places the body that tree joint `j` carries (its child; its parent when the joint is used
/// reversed) from the other body's pose and `X_FM`: X_GB = X_GP X_PF X_FM inverse(X_BM).
JointFrames PlaceBodyThroughJoint(const System& system, int j, const Transform& X_FM,
                                  State& state);

}  // namespace sinew::engine

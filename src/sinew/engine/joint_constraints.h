// The constraints that impose joints and coordinate locks / prescribed motions.
#pragma once

#include <sinew/engine/constraint.h>
#include <sinew/engine/system.h>

#include <memory>

namespace sinew::engine {

/// The constraint of joint `joint_index` of `system`: the six equations
/// inverse(X_GF) * X_GM = X_FM(q) (kParameterized, rows expressed in F) or the direct
/// Cartesian equations (Pin 5, Ball 3, Universal 4, Weld 6; rows in G).
std::shared_ptr<const Constraint> MakeJointConstraint(const System& system, int joint_index);

/// q_i = f(t) for a locked (f = default value) or prescribed coordinate of a parameterized
/// joint (any joint: for Ball/Free rotations, whose u is not qdot, the row is (N(q) u)_i).
std::shared_ptr<const Constraint> MakeCoordinateMotionConstraint(const System& system,
                                                                 int coordinate);

}  // namespace sinew::engine

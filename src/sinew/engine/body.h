// A rigid body of the Cartesian engine: mass properties in its own reference frame B, whose
// origin need not be the mass centre (the seed's ChBodyAuxRef).
#pragma once

#include <sinew/math/types.h>

#include <string>

namespace sinew::engine {

/// Mass properties of one body. Ground is body 0 of every System and never moves.
struct Body {
  std::string name;
  double mass = 0.0;            ///< kg (may be 0 for massless helper bodies)
  Vec3 p_BCm = Vec3::Zero();    ///< mass centre in B, expressed in B (m)
  Mat3 I_Bcm_B = Mat3::Zero();  ///< inertia about the mass centre, B axes (kg m^2)
};

/// Cartesian state of one body in ground G: pose and twist of its reference frame B.
struct BodyState {
  Vec3 p_GB = Vec3::Zero();         ///< origin Bo in G (m)
  Quat quat_GB = Quat::Identity();  ///< orientation R_GB as a unit quaternion
  Vec3 w_GB = Vec3::Zero();         ///< angular velocity, expressed in G (rad/s)
  Vec3 v_GB = Vec3::Zero();         ///< velocity of the origin Bo in G, expressed in G (m/s)
};

}  // namespace sinew::engine

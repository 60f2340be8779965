// The N-link pendulum chain of benchmarks/engine_chain.cc, shared with the engine tests: direct
// pins alternating about z and x, links of 0.5 kg and 0.1 m (mass centre at mid-length), every
// coordinate starting at 0.1 rad and 0.2 rad/s, gravity -9.81 m/s^2 along y.
#pragma once

#include <sinew/engine/system.h>

#include <cmath>
#include <string>

namespace sinew::engine::testing {

/// Builds and finalizes the chain of `n` links with joints of form `form`.
inline System MakeChain(int n, JointForm form = JointForm::kPin) {
  System system(Vec3(0, -9.81, 0));
  const Mat3 y_to_z = Eigen::AngleAxisd(M_PI / 2, Vec3::UnitY()).toRotationMatrix();
  int parent = 0;
  for (int i = 0; i < n; ++i) {
    Body body;
    body.name = "link" + std::to_string(i);
    body.mass = 0.5;
    body.p_BCm = Vec3(0, -0.05, 0);
    body.I_Bcm_B = Vec3(4e-4, 1e-4, 4e-4).asDiagonal();
    const int b = system.AddBody(body);
    // Odd joints turn about x: rotate F and M so that their z axis is the body's x.
    const Mat3 R = (i % 2 == 0) ? Mat3::Identity() : y_to_z;
    const Transform X_PF(R, parent == 0 ? Vec3::Zero() : Vec3(0, -0.1, 0));
    CoordinateDesc c;
    c.name = "q" + std::to_string(i);
    c.default_value = 0.1;
    c.default_speed = 0.2;
    system.AddJoint("pin" + std::to_string(i), parent, X_PF, b, Transform::Rotation(R), form,
                    nullptr, {c});
    parent = b;
  }
  system.Finalize();
  return system;
}

}  // namespace sinew::engine::testing

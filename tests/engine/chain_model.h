// The N-link pendulum chain of benchmarks/engine_chain.cc, shared with the engine tests: direct
// pins alternating about z and x, links of 0.5 kg and 0.1 m (mass centre at mid-length), every
// coordinate starting at 0.1 rad and 0.2 rad/s, gravity -9.81 m/s^2 along y.
#pragma once

#include <sinew/engine/assemble.h>
#include <sinew/engine/system.h>
#include <sinew/forces/constant_distance_constraint.h>

#include <cmath>
#include <memory>
#include <string>

#include "engine/test_models.h"

namespace sinew::engine::testing {

/// Builds and finalizes the chain of `n` links with joints of form `form`. With `couplers` > 0
/// (parameterized joints only), that many levers q[i] = 0.5 q[i + n/2] couple joints half a
/// chain apart (i = 0, n/(2 couplers), ...): extra constraints solved by the Schur complement.
/// With `rods` > 0, that many rods (OpenSim's ConstantDistanceConstraint) hold the tips of links
/// half a chain apart (the same i) at their distance in the default pose: extra constraints
/// that direct joints can carry too.
inline System MakeChain(int n, JointForm form = JointForm::kPin, int couplers = 0, int rods = 0) {
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
    std::shared_ptr<const kinematics::JointModel> model;
    if (form == JointForm::kParameterized) model = std::make_shared<RevoluteModel>(Vec3::UnitZ());
    system.AddJoint("pin" + std::to_string(i), parent, X_PF, b, Transform::Rotation(R), form, model,
                    {c});
    parent = b;
  }
  for (int k = 0; k < couplers; ++k) {
    const int a = k * n / (2 * couplers);
    system.AddConstraint(std::make_shared<LeverConstraint>(a, a + n / 2, 0.5));
  }
  if (rods > 0) {
    const System free_chain = MakeChain(n, form);
    const State pose = MakeDefaultState(free_chain);
    const Vec3 p_BTip(0, -0.1, 0);
    const auto tip = [&](int body) {
      return Vec3(pose.bodies[body].p_GB + pose.bodies[body].quat_GB * p_BTip);
    };
    for (int k = 0; k < rods; ++k) {
      const int b1 = 1 + k * n / (2 * rods), b2 = b1 + n / 2;  // link i is body i + 1
      system.AddConstraint(std::make_shared<forces::ConstantDistanceConstraint>(
          "rod" + std::to_string(k), b1, p_BTip, b2, p_BTip, (tip(b2) - tip(b1)).norm()));
    }
  }
  system.Finalize();
  return system;
}

}  // namespace sinew::engine::testing

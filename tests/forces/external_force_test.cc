// OpenSim's ExternalForce against a hand computation: force and torque expressed in one body
// E, the point in another body P, applied to a third body B, all turned and moved.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/engine/loads.h>
#include <sinew/engine/state.h>
#include <sinew/engine/system.h>
#include <sinew/forces/external_force.h>
#include <sinew/functions/constant.h>
#include <sinew/functions/linear_function.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "engine/test_models.h"

namespace sinew::forces {
namespace {

using engine::testing::MakeBody;

std::array<functions::FunctionPtr, 3> Constants(double x, double y, double z) {
  return {std::make_shared<functions::Constant>(x), std::make_shared<functions::Constant>(y),
          std::make_shared<functions::Constant>(z)};
}

Quat Turn(double angle, const Vec3& axis) { return Quat(Eigen::AngleAxisd(angle, axis)); }

TEST(ExternalForceTest, PointAndForceFramesAreConvertedAsByHand) {
  engine::System system;
  for (const char* name : {"B", "E", "P"}) {
    system.AddBody(MakeBody(name, 1.0, Vec3::Zero(), Mat3::Identity()));
  }
  engine::State state;
  state.t = 0.5;
  state.bodies.resize(4);
  // B at (1, 2, 3) turned 90 deg about z; E turned 90 deg about x; P at (0.5, 0, -1) turned
  // 90 deg about y.
  state.bodies[1].p_GB = Vec3(1, 2, 3);
  state.bodies[1].quat_GB = Turn(M_PI / 2, Vec3::UnitZ());
  state.bodies[2].p_GB = Vec3(7, 8, 9);
  state.bodies[2].quat_GB = Turn(M_PI / 2, Vec3::UnitX());
  state.bodies[3].p_GB = Vec3(0.5, 0, -1);
  state.bodies[3].quat_GB = Turn(M_PI / 2, Vec3::UnitY());

  // f_E = (0, 1 + 2t, 0) = (0, 2, 0) at t = 0.5; p_P = (1, 0, 0); tau_E = (0, 0, 2).
  ExternalForceFunctions functions;
  functions.force = Constants(0, 0, 0);
  functions.force[1] = std::make_shared<functions::LinearFunction>(2.0, 1.0);
  functions.point = Constants(1, 0, 0);
  functions.torque = Constants(0, 0, 2);
  const ExternalForce force("grf", "B", {1, 2, 3}, functions);

  // By hand: a quarter turn about x takes y to z and z to -y, so f_G = (0, 0, 2) and
  // tau_G = (0, -2, 0). A quarter turn about y takes x to -z: p_GQ = (0.5, 0, -1) + (0, 0, -1)
  // = (0.5, 0, -2). From Bo: r = p_GQ - p_GB = (-0.5, -2, -5), which B (a quarter turn about z,
  // undone by (x, y) -> (y, -x)) sees as p_BQ = (-2, 0.5, -5). Torque about Bo:
  // r x f_G + tau_G = (-2*2 - (-5)*0, (-5)*0 - (-0.5)*2, 0) + (0, -2, 0) = (-4, -1, 0).
  const engine::ForceContext context{system, state};
  engine::Loads loads(4, 0);
  force.AddLoads(context, loads);
  const SpatialVec expected_B = (SpatialVec() << -4, -1, 0, 0, 0, 2).finished();
  EXPECT_LT((loads.body[1] - expected_B).norm(), 1e-14) << loads.body[1].transpose();
  for (int b : {0, 2, 3}) EXPECT_EQ(loads.body[b].norm(), 0.0) << b;

  EXPECT_EQ(force.RecordLabels(system),
            (std::vector<std::string>{"B_grf_Fx", "B_grf_Fy", "B_grf_Fz", "B_grf_px", "B_grf_py",
                                      "B_grf_pz", "B_grf_Tx", "B_grf_Ty", "B_grf_Tz"}));
  std::vector<double> values;
  force.CalcRecordValues(context, values);
  const std::vector<double> hand = {0, 0, 2, -2, 0.5, -5, 0, -2, 0};
  ASSERT_EQ(values.size(), hand.size());
  for (size_t i = 0; i < hand.size(); ++i) EXPECT_NEAR(values[i], hand[i], 1e-14) << i;

  // Supported on B, E and P: its loads depend on all three poses.
  EXPECT_EQ(force.Support()->bodies, (std::vector<int>{1, 2, 3}));
}

TEST(ExternalForceTest, WithoutAPointTheForceActsAtTheBodyOrigin) {
  engine::System system;
  system.AddBody(MakeBody("B", 1.0, Vec3::Zero(), Mat3::Identity()));
  engine::State state;
  state.bodies.resize(2);
  state.bodies[1].p_GB = Vec3(1, 2, 3);
  state.bodies[1].quat_GB = Turn(0.3, Vec3(1, 2, 3).normalized());
  ExternalForceFunctions functions;
  functions.force = Constants(4, 5, 6);  // in ground (E = 0)
  const ExternalForce force("push", "B", {1, 0, 0}, functions);
  engine::Loads loads(2, 0);
  force.AddLoads(engine::ForceContext{system, state}, loads);
  EXPECT_EQ(loads.body[1], (SpatialVec() << 0, 0, 0, 4, 5, 6).finished());
  EXPECT_EQ(force.RecordLabels(system),
            (std::vector<std::string>{"B_push_Fx", "B_push_Fy", "B_push_Fz"}));
}

TEST(ExternalForceTest, NeitherForceNorTorqueOrAPointWithoutForceIsRefused) {
  ExternalForceFunctions none;
  EXPECT_THROW(ExternalForce("empty", "B", {1, 0, 0}, none), Error);
  ExternalForceFunctions point_only;
  point_only.point = Constants(0, 0, 0);
  point_only.torque = Constants(0, 0, 1);
  EXPECT_THROW(ExternalForce("point", "B", {1, 0, 0}, point_only), Error);
}

}  // namespace
}  // namespace sinew::forces

// Coupler-driven coordinates in the kinematics path: set from their drivers by the file's
// coupling function and scale factor, checked at the spline's own data points (hand values
// from the file) and on Rajagopal2016's patellae (beta = knee angle).
#include <gtest/gtest.h>
#include <sinew/io/osim_reader.h>
#include <sinew/kinematics/coordinate_couplers.h>
#include <sinew/kinematics/kinematic_tree.h>

#include <string>
#include <vector>

namespace sinew::kinematics {
namespace {

const std::string kData = SINEW_TEST_DATA_DIR;

TEST(CoordinateCouplersTest, SplineCouplerGivesTheFileDataPointsScaled) {
  // springs.osim: follower_x = 0.5 spline(arm_angle), the spline through
  // (-1.5, 0.3) (-0.8, -0.1) (-0.2, 0.05) (0.4, 0.2) (1, -0.15) (1.6, 0.1).
  const model::ModelSpec spec = io::ReadOsim(kData + "/sinew/springs.osim");
  const CoordinateCouplers couplers(spec);
  const int arm = spec.FindCoordinate("arm_angle"), follower = spec.FindCoordinate("follower_x");
  ASSERT_GE(arm, 0);
  ASSERT_GE(follower, 0);
  EXPECT_TRUE(couplers.Drives(follower));
  EXPECT_FALSE(couplers.Drives(arm));
  const double x[] = {-1.5, -0.8, -0.2, 0.4, 1, 1.6}, y[] = {0.3, -0.1, 0.05, 0.2, -0.15, 0.1};
  std::vector<double> q = KinematicTree(spec).default_q();
  for (int k = 0; k < 6; ++k) {
    q[arm] = x[k];
    couplers.Apply(q);
    EXPECT_NEAR(q[follower], 0.5 * y[k], 1e-12) << "arm_angle = " << x[k];
  }
}

TEST(CoordinateCouplersTest, RajagopalPatellaeFollowTheKnees) {
  const model::ModelSpec spec =
      io::ReadOsim(kData + "/opensim-org/opensim-models/Models/Rajagopal/Rajagopal2016.osim");
  const CoordinateCouplers couplers(spec);
  std::vector<double> q = KinematicTree(spec).default_q();
  q[spec.FindCoordinate("knee_angle_r")] = 0.8;
  q[spec.FindCoordinate("knee_angle_l")] = 0.3;
  couplers.Apply(q);
  EXPECT_EQ(q[spec.FindCoordinate("knee_angle_r_beta")], 0.8);  // LinearFunction 1 x + 0
  EXPECT_EQ(q[spec.FindCoordinate("knee_angle_l_beta")], 0.3);
}

}  // namespace
}  // namespace sinew::kinematics

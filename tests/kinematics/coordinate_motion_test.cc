#include <gtest/gtest.h>
#include <sinew/kinematics/coordinate_motion.h>

#include <numbers>
#include <string>
#include <vector>

namespace sinew {
namespace {

model::ModelSpec ThreeCoordinates() {
  model::ModelSpec spec;
  const char* names[] = {"knee_angle_r", "knee_tx", "coupled"};
  const model::MotionType types[] = {model::MotionType::kRotational,
                                     model::MotionType::kTranslational,
                                     model::MotionType::kCoupled};
  for (int i = 0; i < 3; ++i) {
    model::CoordinateSpec c;
    c.name = names[i];
    c.path = std::string("/jointset/knee_r/") + names[i];
    c.motion_type = types[i];
    spec.coordinates.push_back(c);
  }
  return spec;
}

TEST(CoordinateMotionTest, MapsNamesAndPathsAndReportsUnknownColumns) {
  const model::ModelSpec spec = ThreeCoordinates();
  const std::vector<std::string> labels = {"time", "/jointset/knee_r/knee_angle_r/value",
                                           "/jointset/knee_r/knee_angle_r/speed", "knee_tx",
                                           "elbow_flex"};
  const kinematics::MotionColumnMap map = kinematics::MapMotionColumns(spec, labels);
  EXPECT_EQ(map.coordinate, (std::vector<int>{model::kNone, 0, model::kNone, 1, model::kNone}));
  EXPECT_EQ(map.unknown, (std::vector<std::string>{"elbow_flex"}));
  EXPECT_EQ(map.missing, (std::vector<int>{2}));
}

TEST(CoordinateMotionTest, ConvertsDegreesOnlyForRotationalCoordinates) {
  const model::ModelSpec spec = ThreeCoordinates();
  const std::vector<std::string> labels = {"time", "knee_angle_r", "knee_tx", "coupled"};
  const kinematics::MotionColumnMap map = kinematics::MapMotionColumns(spec, labels);
  std::vector<double> q = {9, 9, 9};
  const std::vector<double> row = {0.5, 90.0, 0.25, 30.0};
  kinematics::ApplyMotionRow(spec, map, row, /*in_degrees=*/true, q);
  EXPECT_DOUBLE_EQ(q[0], std::numbers::pi / 2);
  EXPECT_DOUBLE_EQ(q[1], 0.25);
  EXPECT_DOUBLE_EQ(q[2], 30.0);  // OpenSim leaves coupled coordinates as written
  kinematics::ApplyMotionRow(spec, map, row, /*in_degrees=*/false, q);
  EXPECT_DOUBLE_EQ(q[0], 90.0);
}

TEST(CoordinateMotionTest, MissingCoordinatesKeepTheirValues) {
  const model::ModelSpec spec = ThreeCoordinates();
  const std::vector<std::string> labels = {"time", "knee_tx"};
  const kinematics::MotionColumnMap map = kinematics::MapMotionColumns(spec, labels);
  std::vector<double> q = {0.1, 0.2, 0.3};
  const std::vector<double> row = {0.0, -0.5};
  kinematics::ApplyMotionRow(spec, map, row, true, q);
  EXPECT_EQ(q, (std::vector<double>{0.1, -0.5, 0.3}));
}

}  // namespace
}  // namespace sinew

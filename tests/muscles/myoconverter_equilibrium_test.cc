// Equilibrium fiber forces against OpenSim's, as stored with MyoConverter's validation data
// (reference-csv/<Model>/muscle_kinetics.csv): at activation 1 and the musculotendon length
// OpenSim computed at each pose, with zero speeds, OpenSim's equilibrateMuscles gave the
// active and passive fiber forces (along the fiber) and the "total" force, which is the
// tendon force: (active + passive) cos(pennation), as the numbers show (TRIlat at 0.16661 m:
// 453.47 N active, 437.80 N total, pennation 0.26 rad at equilibrium). The test starts from the
// csv's mtu_length, so it checks the muscle model alone (paths and wrapping are tested in
// tests/paths).
#include <gtest/gtest.h>
#include <myoconverter_csv.h>
#include <sinew/model/model_spec.h>
#include <sinew/muscles/path_actuator.h>
#include <sinew/opensim/parser.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace sinew::muscles {
namespace {


// Whether a pose "coord=value;coord=value" puts a coordinate outside its range. MyoConverter
// prints poses with 5 digits, so a sweep's end can lie just beyond a range (-2.0944 below
// -2.0943951); OpenSim clamped such coordinates and assembled the model, and on those rows
// the stored forces belong to a musculotendon length about 1e-6 m from the printed one
// (rect_fem_r at 0.500907347 m: active and tendon force both match Sinew's at a length
// 1.2e-6 m shorter, and an independent transcription of OpenSim's Newton iteration gives
// Sinew's values to 1e-12 at the printed length).
bool PoseOutsideRange(const model::ModelSpec& spec, const std::string& pose) {
  std::stringstream entries(pose);
  std::string entry;
  while (std::getline(entries, entry, ';')) {
    const size_t eq = entry.find('=');
    const std::string name = entry.substr(0, eq);
    const double value = std::stod(entry.substr(eq + 1));
    for (const model::CoordinateSpec& c : spec.coordinates) {
      if (c.name == name && (value < c.range_min || value > c.range_max)) return true;
    }
  }
  return false;
}


// Every row of a model's csv: the muscle's model, equilibrated at the row's activation and
// length with zero speed, gives OpenSim's forces to 1e-6 of the total (at least 1 N).
//
// Rows where OpenSim wrote 0, 0, 0 although the tendon is stretched are not equilibria: a
// muscle at activation 1 whose tendon pulls must have a fiber force. There Sinew finds that
// even the shortest fiber (minimum fiber length) pulls harder than the tendon, the case in
// which OpenSim's Thelen2003Muscle stops its Newton iteration at the minimum length (its
// derivatives are singular there when the minimum is 0); MyoConverter then wrote zeros. Those
// rows are counted (`expected_at_minimum`), not compared.
void ExpectEquilibriumForces(const std::string& model_dir, const std::string& osim,
                             int expected_rows, int expected_at_minimum = 0,
                             int expected_outside_range = 0) {
  const std::string data = std::string(SINEW_TEST_DATA_DIR) + "/MyoHub/myoconverter/";
  OpenSimParser parser;
  const auto system = parser.Parse(data + "models/osim/" + model_dir + "/" + osim);
  const std::vector<testing::MuscleKineticsRow> rows =
      testing::ReadMuscleKinetics(data + "reference-csv/" + model_dir + "/muscle_kinetics.csv");
  ASSERT_EQ(static_cast<int>(rows.size()), expected_rows);
  double worst = 0.0;
  std::string worst_row;
  int at_minimum = 0, outside_range = 0;
  double worst_outside = 0.0;
  for (const testing::MuscleKineticsRow& row : rows) {
    const auto& forces = parser.GetReport().forces();
    const auto it = forces.find(row.muscle);
    ASSERT_NE(it, forces.end()) << row.muscle;
    const auto* actuator = dynamic_cast<const PathActuator*>(it->second.load.get());
    ASSERT_NE(actuator, nullptr) << row.muscle << " is not simulated as a path actuator";
    const TensionModel& model = actuator->model();
    VecX z(2);
    z << row.activation, 0.0;
    const PathKinematics path{row.mtu_length, 0.0};
    const EquilibriumStatus status = model.Equilibrate(path, row.muscle, z);
    const MuscleQuantities q = model.Calc(z, row.activation, path);
    if (row.active_force == 0.0 && row.passive_force == 0.0 && row.total_force == 0.0 && q.tendon_force > 0.0) {
      EXPECT_EQ(status, EquilibriumStatus::kFiberAtMinimumLength) << row.muscle;
      ++at_minimum;
      continue;
    }
    // OpenSim's equilibrium is solved to 1e-8 max_isometric_force; the csv prints 10 digits.
    // Rows of a pose outside a range: the forces of a length within 2e-6 m of the printed
    // one, times a musculotendon stiffness below 1.2e4 N/m per N of force (5e-5 relative
    // at most on these models' rows; see PoseOutsideRange).
    const double scale = std::max(std::abs(row.total_force), 1.0);
    const bool outside = PoseOutsideRange(parser.GetSpec(), row.pose);
    outside_range += outside ? 1 : 0;
    const double bound = outside ? 5e-5 : 1e-6;
    for (const auto& [value, reference] :
         {std::pair{q.active_fiber_force, row.active_force},
          std::pair{q.passive_fiber_force, row.passive_force}, std::pair{q.tendon_force, row.total_force}}) {
      const double error = std::abs(value - reference) / scale;
      if (outside) worst_outside = std::max(worst_outside, error);
      if (!outside && error > worst) {
        worst = error;
        worst_row = row.muscle + " at mtu_length " + std::to_string(row.mtu_length);
      }
      EXPECT_LT(error, bound) << row.muscle << " mtu_length " << row.mtu_length << ": " << value
                              << " vs OpenSim's " << reference << " (active, passive, tendon "
                              << q.active_fiber_force << ", " << q.passive_fiber_force << ", "
                              << q.tendon_force << "; fiber " << q.fiber_length << " m)";
    }
  }
  EXPECT_EQ(at_minimum, expected_at_minimum);
  EXPECT_EQ(outside_range, expected_outside_range);
  std::printf(
      "%s: worst relative error %.2e (%s); %d rows at the minimum fiber length, %d of a pose "
      "outside a range (worst %.2e)\n",
      model_dir.c_str(), worst, worst_row.c_str(), at_minimum, outside_range, worst_outside);
}

TEST(MyoConverterEquilibriumTest, Arm26ThelenMusclesMatchOpenSim) {
  ExpectEquilibriumForces("Arm26", "arm26.osim", 90, 0, 11);
}

TEST(MyoConverterEquilibriumTest, Leg6Dof9MuscThelenMusclesMatchOpenSim) {
  ExpectEquilibriumForces("Leg6Dof9Musc", "leg6dof9musc.osim", 135, 0, 21);
}

TEST(MyoConverterEquilibriumTest, TugOfWarThelenMusclesMatchOpenSim) {
  ExpectEquilibriumForces("TugOfWar", "tugofwar.osim", 30);
}

TEST(MyoConverterEquilibriumTest, Gait2354ThelenMusclesMatchOpenSim) {
  ExpectEquilibriumForces("Gait2354Simbody", "gait2354.osim", 810, 4, 448);
}

// Gait10dof18musc's 18 Millard2012EquilibriumMuscles built by the parser as path actuators:
// the element's model gives OpenSim's equilibrium forces (millard2012_myoconverter_test.cc
// checks the same rows on the pure functions).
TEST(MyoConverterEquilibriumTest, Gait10dof18muscMillardMusclesThroughTheElementMatchOpenSim) {
  ExpectEquilibriumForces("Gait10dof18musc", "gait10dof18musc.osim", 270, 0, 38);
}

}  // namespace
}  // namespace sinew::muscles

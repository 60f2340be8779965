// Millard2012EquilibriumMuscle's equilibrium against OpenSim: MyoConverter's reference table of
// Gait10dof18musc (OpenSim's equilibrateMuscles at activation 1 and several poses, then the
// muscles' active, passive and total fiber forces), every row of every muscle. The musculotendon
// length comes from the table, so no path is involved.
#include <gtest/gtest.h>
#include <myoconverter_csv.h>
#include <sinew/io/osim_reader.h>
#include <sinew/muscles/millard2012_equilibrium.h>
#include <sinew/muscles/millard2012_spec.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace sinew::muscles {
namespace {

const std::string kData = std::string(SINEW_TEST_DATA_DIR) + "/MyoHub/myoconverter/";



// Active and total fiber force (the tendon force, which equals the fiber force along the tendon
// at equilibrium) within 1e-6 relative, as issue 12 asks; where OpenSim's are 0 (48 rows: the
// fiber pushed to its minimum length, its state clamped) Sinew's must be 0 too. The largest
// differences (7.1e-7, vasti at knee 0.1745 rad, where the fiber is near its shortest active
// length and the active force is 0.005 N) come from the table's path length printed to 10
// digits: half a unit in its last digit moves Sinew's own active force there by 9.2e-7. The
// passive force is compared relatively where it exceeds what the damping of OpenSim's
// equilibrium residual can produce (its tolerance 1e-8 Fiso, over cos(pennation)); below that,
// where the passive element is slack and only the residual's damping remains (values of 1e-13
// to 1e-7 N), within that bound.
TEST(Millard2012MyoConverterTest, Gait10dof18muscEquilibriumForcesMatchOpenSim) {
  const std::string osim = kData + "models/osim/Gait10dof18musc/gait10dof18musc.osim";
  const model::ModelSpec spec = io::ReadOsim(osim);
  std::map<std::string, Millard2012Muscle> muscles;
  for (const model::ForceSpec& force : spec.forces) {
    if (force.type == "Millard2012EquilibriumMuscle") {
      muscles.emplace(force.name, ReadMillard2012Muscle(spec, force));
    }
  }
  ASSERT_EQ(muscles.size(), 18u);
  const std::vector<testing::MuscleKineticsRow> rows =
      testing::ReadMuscleKinetics(kData + "reference-csv/Gait10dof18musc/muscle_kinetics.csv");
  ASSERT_EQ(rows.size(), 270u);
  double worst_active = 0, worst_total = 0, worst_passive = 0;
  int clamped = 0, passive_compared = 0;
  // |value - reference| <= 1e-6 |reference| + floor; returns the relative error (0 if exact).
  auto expect_close = [](double value, double reference, double floor, const std::string& what) {
    const double error = std::abs(value - reference);
    EXPECT_LE(error, 1e-6 * std::abs(reference) + floor)
        << what << ": " << value << " vs OpenSim's " << reference;
    return error == 0.0 ? 0.0 : error / std::abs(reference);
  };
  for (const testing::MuscleKineticsRow& row : rows) {
    const auto it = muscles.find(row.muscle);
    ASSERT_NE(it, muscles.end()) << row.muscle;
    const Millard2012Muscle& m = it->second;
    const double fiso = m.parameters().max_isometric_force;
    const Millard2012Equilibrium eq =
        SolveMillard2012Equilibrium(m, row.activation, row.mtu_length, 0.0);
    const std::string where = row.muscle + " at " + row.pose;
    ASSERT_EQ(eq.status, Millard2012Equilibrium::Status::kConverged) << where;
    EXPECT_LE(std::abs(eq.solution_error), 1e-8 * fiso) << where;
    const Millard2012Dynamics d =
        CalcMillard2012Dynamics(m, row.activation, eq.fiber_length, row.mtu_length, 0.0);
    if (d.fiber_state_clamped) ++clamped;
    worst_active = std::max(
        worst_active, expect_close(d.active_fiber_force, row.active_force, 0.0, where + " active"));
    worst_total = std::max(worst_total,
                           expect_close(d.tendon_force, row.total_force, 0.0, where + " tendon"));
    expect_close(d.fiber_force_along_tendon, row.total_force, 0.0, where + " fiber along tendon");
    const double residual_damping = 1e-8 * fiso / d.cos_pennation;
    if (std::abs(row.passive_force) > residual_damping) {
      worst_passive = std::max(worst_passive,
                               expect_close(d.passive_fiber_force, row.passive_force, 0.0, where));
      ++passive_compared;
    } else {
      expect_close(d.passive_fiber_force, row.passive_force, residual_damping, where + " passive");
    }
  }
  EXPECT_EQ(clamped, 48);
  EXPECT_GT(passive_compared, 50);
  std::printf("worst relative: active %.2g, total %.2g, passive %.2g (%d rows above the floor)\n",
              worst_active, worst_total, worst_passive, passive_compared);
}

}  // namespace
}  // namespace sinew::muscles

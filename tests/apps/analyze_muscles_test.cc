// `sinew analyze` on a states file with muscle states (Thelen2003Muscle, Schutte1993Muscle): its
// FiberLength, TendonLength and force tables against the run that wrote the states. The tendon
// forces simulate wrote in forces.sto come from the engine's path (body poses of the simulation);
// analyze's from the spec's kinematics at the states file's coordinates: two computations of the
// same force.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "apps/cli_test_util.h"
#include "engine/test_models.h"

namespace sinew {
namespace {

using testing::CliRun;

class AnalyzeMusclesTest : public testing::CliTest {
 protected:
  // Simulates `model` 0.2 s from muscle equilibrium with `excitation`, analyzes its states file
  // and compares the tables of `muscles` with the run. The simulation's body poses hold the
  // joint constraints to about 1e-13 m after projection, not exactly the poses of q; times the
  // stiffness of a stiff tendon (arm26's BRA: about 8e5 N/m) that is 1e-7 N.
  void ExpectTablesAgreeWithTheRun(const std::string& model, const std::string& excitation,
                                   const std::vector<std::string>& muscles) {
    const CliRun run = Run("simulate " + model +
                           " --duration 0.2 --report-interval 0.05 --equilibrate-muscles --quiet "
                           "--excitation " +
                           excitation + " --out " + Path("run"));
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const CliRun analyze =
        Run("analyze " + model + " --motion " + Path("run/states.sto") + " --out " + Path("an"));
    ASSERT_EQ(analyze.exit_code, 0) << analyze.err;
    EXPECT_EQ(analyze.err.find("not used"), std::string::npos) << analyze.err;  // states used
    const auto states = engine::testing::ReadStoColumns(Path("run/states.sto"));
    const auto forces = engine::testing::ReadStoColumns(Path("run/forces.sto"));
    const auto fiber = engine::testing::ReadStoColumns(Path("an/FiberLength.sto"));
    const auto tendon = engine::testing::ReadStoColumns(Path("an/TendonForce.sto"));
    const auto length = engine::testing::ReadStoColumns(Path("an/Length.sto"));
    const auto tendon_length = engine::testing::ReadStoColumns(Path("an/TendonLength.sto"));
    for (const std::string& muscle : muscles) {
      const auto& f = forces.at(muscle);
      ASSERT_EQ(tendon.at(muscle).size(), f.size()) << muscle;
      for (size_t r = 0; r < f.size(); ++r) {
        EXPECT_NEAR(tendon.at(muscle)[r], f[r], 1e-7 * (1 + std::abs(f[r])))
            << muscle << " row " << r;
        EXPECT_EQ(fiber.at(muscle)[r], states.at("/forceset/" + muscle + "/fiber_length")[r]);
        EXPECT_LT(tendon_length.at(muscle)[r], length.at(muscle)[r]);
      }
    }
  }
};

// arm26's Thelen2003Muscles (measured 4.9e-8 N).
TEST_F(AnalyzeMusclesTest, MuscleTablesOfAStatesFileAgreeWithTheRun) {
  ExpectTablesAgreeWithTheRun(
      std::string(SINEW_TEST_DATA_DIR) + "/opensim-org/opensim-models/Models/Arm26/arm26.osim",
      "BIClong=constant:0.5", {"TRIlong", "TRIlat", "TRImed", "BIClong", "BICshort", "BRA"});
}

// wrist_mass.osim's Schutte1993Muscles (flexors and extensors of the wrist and fingers).
TEST_F(AnalyzeMusclesTest, SchutteMuscleTablesOfAStatesFileAgreeWithTheRun) {
  ExpectTablesAgreeWithTheRun(
      std::string(SINEW_TEST_DATA_DIR) +
          "/opensim-org/opensim-core/OpenSim/Simulation/Test/wrist_mass.osim",
      "FCR=constant:0.5", {"FCR", "FCU", "ECU_post-surgery", "ECRL", "ECRB", "PL", "EDCI", "FPL"});
}

}  // namespace
}  // namespace sinew

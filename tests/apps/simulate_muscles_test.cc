// `sinew simulate` with muscles: equilibrium on request, the class rename OpenSim's forward
// tests use, and their errors.
#include <gtest/gtest.h>

#include <string>

#include "apps/cli_test_util.h"
#include "engine/test_models.h"

namespace sinew {
namespace {

using testing::CliRun;

const std::string kArm26 =
    std::string(SINEW_TEST_DATA_DIR) + "/opensim-org/opensim-models/Models/Arm26/arm26.osim";

class SimulateMusclesTest : public testing::CliTest {};

TEST_F(SimulateMusclesTest, EquilibrateMusclesMovesFibersOffTheirDefaults) {
  const CliRun plain = Run("simulate " + kArm26 + " --duration 0 --quiet --out " + Path("plain"));
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  const CliRun eq =
      Run("simulate " + kArm26 + " --duration 0 --quiet --equilibrate-muscles --out " + Path("eq"));
  ASSERT_EQ(eq.exit_code, 0) << eq.err;
  const auto a = engine::testing::ReadStoColumns(Path("plain/states.sto"));
  const auto b = engine::testing::ReadStoColumns(Path("eq/states.sto"));
  // Without equilibrium: the file's default_fiber_length (TRIlong's optimal length 0.134 m).
  EXPECT_EQ(a.at("/forceset/TRIlong/fiber_length").front(), 0.134);
  EXPECT_NE(b.at("/forceset/TRIlong/fiber_length").front(), 0.134);
  EXPECT_EQ(b.at("/forceset/TRIlong/activation").front(), 0.05);  // the default activation
}

TEST_F(SimulateMusclesTest, RenamedClassIsSimulatedAndItsMissingEquilibriumIsAnError) {
  const std::string rename = " --rename-force-class Thelen2003Muscle=Thelen2003Muscle_Deprecated";
  const CliRun run =
      Run("simulate " + kArm26 + rename + " --duration 0.01 --quiet --out " + Path("dep"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const CliRun eq = Run("simulate " + kArm26 + rename +
                        " --duration 0.01 --quiet --equilibrate-muscles --out " + Path("eq"));
  EXPECT_EQ(eq.exit_code, 2) << eq.err;
  EXPECT_NE(eq.err.find(kArm26 + ": /forceset/TRIlong: muscle-tendon equilibrium is not "
                                 "implemented for Thelen2003Muscle_Deprecated"),
            std::string::npos)
      << eq.err;
  const CliRun bad = Run("simulate " + kArm26 +
                         " --rename-force-class Thelen2003Muscle --duration 0 --out " + Path("b"));
  EXPECT_EQ(bad.exit_code, 2) << bad.err;
  EXPECT_NE(bad.err.find("--rename-force-class: expects OLD=NEW"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace sinew

// `sinew simulate` with model constraints: constraints.sto with --report-constraint-forces
// (OpenSim's record labels, the load a weld carries), and a model whose constraints cannot be
// assembled, refused with exit code 2 and the constraint named.
#include <gtest/gtest.h>
#include <sinew/io/storage.h>

#include <cmath>
#include <fstream>
#include <string>

#include "apps/cli_test_util.h"

namespace sinew {
namespace {

const std::string kData = SINEW_TEST_DATA_DIR;

using testing::CliTest;

class SimulateConstraintsTest : public CliTest {};

TEST_F(SimulateConstraintsTest, ConstraintForcesAreWrittenAtTheReportTimes) {
  const auto run = Run("simulate " + kData + "/sinew/constraints.osim --duration 0.2 " +
                       "--report-constraint-forces --out " + Path("out"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("constraints.sto"), std::string::npos) << run.out;
  const io::Storage states = io::ReadStorage(Path("out") + "/states.sto");
  const io::Storage forces = io::ReadStorage(Path("out") + "/constraints.sto");
  EXPECT_EQ(forces.Metadata("status"), "complete");
  ASSERT_EQ(forces.NumRows(), states.NumRows());
  EXPECT_EQ(forces.time, states.time);
  EXPECT_EQ(forces.labels.size(), 4u * 12u);  // 4 constraints x 2 bodies x 6
  // The welded body (2 kg) hangs still all along: OpenSim's sign, its weight pulling down.
  const int fy = forces.FindColumn("weld_welded_Fy");
  const int ground_fy = forces.FindColumn("weld_ground_Fy");
  ASSERT_GE(fy, 0);
  ASSERT_GE(ground_fy, 0);
  for (int row = 0; row < forces.NumRows(); ++row) {
    // The file prints about 9 significant digits.
    EXPECT_NEAR(forces.Value(row, fy), -2.0 * 9.80665, 1e-7) << row;
    EXPECT_NEAR(forces.Value(row, ground_fy), 2.0 * 9.80665, 1e-7) << row;
  }
}

TEST_F(SimulateConstraintsTest, WithoutTheOptionNoConstraintsFile) {
  const auto run = Run("simulate " + kData + "/sinew/constraints.osim --duration 0.01 --quiet " +
                       "--out " + Path("out"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_FALSE(std::filesystem::exists(Path("out") + "/constraints.sto"));
}

TEST_F(SimulateConstraintsTest, UnsatisfiableConstraintIsNamed) {
  // reach.osim with the tip asked to stay 4 m from a point it can come at most 1.76 m from.
  std::string text = testing::ReadText(kData + "/sinew/reach.osim");
  const std::string from = "<constant_distance>0.75<";
  text.replace(text.find(from), from.size(), "<constant_distance>4<");
  std::ofstream(Path("unreachable.osim")) << text;
  const auto run =
      Run("simulate " + Path("unreachable.osim") + " --duration 0.1 --out " + Path("out"));
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("cannot assemble a state that satisfies the constraints"),
            std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("'reach'"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace sinew

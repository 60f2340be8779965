// Tables read for a model (kinematics --motion, export and render --motion/--states, simulate
// --initial-states): a time column that is not finite or not increasing, or a NaN/inf value in a
// column that names a coordinate, is an error naming the file, column and row, never NaN in
// bodies.sto or a .glb; a repeated label and a column naming no coordinate are warnings.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "apps/cli_test_util.h"

namespace sinew {
namespace {

using testing::CliRun;

const std::string kModel = std::string(SINEW_TEST_DATA_DIR) +
                           "/opensim-org/opensim-core/Applications/Analyze/tests/resources/"
                           "SinglePin.osim";

class TablesTest : public testing::CliTest {
 protected:
  // Writes a table of SinglePin's coordinate r1_z (and `extra` columns) with `rows`.
  std::string Table(const std::string& labels, const std::string& rows) const {
    const std::string path = Path("motion.sto");
    std::ofstream(path) << "motion\nversion=1\ninDegrees=no\nendheader\n" << labels << "\n" << rows;
    return path;
  }
  // Expects every command that reads a table to fail on `table` with `message`.
  void ExpectEveryCommandRefuses(const std::string& table, const std::string& message) const {
    const std::string commands[] = {
        "kinematics " + kModel + " --motion " + table + " --out " + Path("k"),
        "export " + kModel + " --vis none --motion " + table + " --out " + Path("m.glb"),
        "render " + kModel + " --vis none --motion " + table + " --out " + Path("m.png"),
        "simulate " + kModel + " --duration 0.01 --initial-states " + table + " --out " + Path("s"),
    };
    for (const std::string& command : commands) {
      const CliRun run = Run(command);
      EXPECT_EQ(run.exit_code, 2) << command << "\n" << run.err;
      EXPECT_NE(run.err.find("sinew: error: " + table + ": " + message), std::string::npos)
          << command << "\n"
          << run.err;
    }
    EXPECT_FALSE(std::filesystem::exists(Path("k/bodies.sto")));
    EXPECT_FALSE(std::filesystem::exists(Path("m.glb")));
    EXPECT_FALSE(std::filesystem::exists(Path("s/bodies.sto")));
  }
};

TEST_F(TablesTest, AGoodTableIsUsedByEveryCommand) {
  const std::string table = Table("time\tr1_z", "0\t0.1\n0.5\t0.2\n");
  EXPECT_EQ(Run("kinematics " + kModel + " --motion " + table + " --out " + Path("k")).exit_code,
            0);
  EXPECT_EQ(Run("export " + kModel + " --vis none --motion " + table + " --out " + Path("m.glb"))
                .exit_code,
            0);
}

TEST_F(TablesTest, NaNOrInfiniteValuesInACoordinateColumnAreErrors) {
  ExpectEveryCommandRefuses(
      Table("time\tr1_z", "0\t0.1\n0.5\tnan\n"),
      "column 'r1_z', row 2 (time 0.5): nan is not a finite number, and the column names a "
      "coordinate");
  ExpectEveryCommandRefuses(Table("time\t/jointset/pin1/r1_z/value", "0\t-inf\n"),
                            "column '/jointset/pin1/r1_z/value', row 1 (time 0): -inf");
}

TEST_F(TablesTest, NaNInAColumnNamingNoCoordinateIsNotUsedAndNotAnError) {
  const std::string table = Table("time\tr1_z\tforce", "0\t0.1\tnan\n");
  const CliRun run = Run("kinematics " + kModel + " --motion " + table + " --out " + Path("k"));
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("1 column is not used (force): they name no coordinate"),
            std::string::npos)
      << run.err;
  EXPECT_EQ(testing::ReadText(Path("k/bodies.sto")).find("nan"), std::string::npos);
}

TEST_F(TablesTest, TimeThatIsNotFiniteOrDoesNotIncreaseIsAnError) {
  ExpectEveryCommandRefuses(Table("time\tr1_z", "0\t0\n0.5\t0\n0.5\t0\n"),
                            "column 'time' must increase, but row 3 has 0.5, the same as row 2");
  ExpectEveryCommandRefuses(Table("time\tr1_z", "0\t0\n1\t0\n0.5\t0\n"),
                            "column 'time' must increase, but row 3 has 0.5, less than row 2 (1)");
  ExpectEveryCommandRefuses(Table("time\tr1_z", "nan\t0\n"),
                            "column 'time', row 1: nan is not a finite time");
}

TEST_F(TablesTest, ARepeatedLabelIsAWarningAndTheFirstColumnIsUsed) {
  const std::string table = Table("time\tr1_z\tr1_z", "0\t0.25\t0.75\n");
  const CliRun run = Run("kinematics " + kModel + " --motion " + table + " --out " + Path("k"));
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("sinew: warning: " + table +
                         ": 1 column label is repeated (r1_z); the first column of each is used"),
            std::string::npos)
      << run.err;
}

TEST_F(TablesTest, ExportAndRenderNoteAColumnNamingNoCoordinate) {
  const std::string table = Table("time\tr1_z\tbogus", "0\t0.1\t1\n");
  const std::string note =
      "sinew: note: 1 coordinates or columns not matched between model and table; first: column "
      "'bogus' names no coordinate; ignored\n";
  for (const std::string& command :
       {"export " + kModel + " --vis none --motion " + table + " --out " + Path("m.glb"),
        "render " + kModel + " --vis none --motion " + table + " --out " + Path("m.png")}) {
    const CliRun run = Run(command);
    EXPECT_EQ(run.exit_code, 0) << command << "\n" << run.err;
    EXPECT_NE(run.err.find(note), std::string::npos) << command << "\n" << run.err;
  }
}

}  // namespace
}  // namespace sinew

// Motion and states files without an inDegrees line are read as OpenSim's Storage reads them
// (Storage.cpp: radians by default; an old .mot, with no version or version=0, is a SIMM
// motion in degrees), and the CLI warns when a file read as radians has rotational values
// beyond 2*pi, which look like degrees. SinglePin's rod1 hangs 0.5 m below a z pin, so its mass
// centre is at (0.5 sin q, -0.5 cos q): the angle used can be read back from bodies.sto.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <string>

#include "apps/cli_test_util.h"
#include "engine/test_models.h"

namespace sinew {
namespace {

using engine::testing::ReadStoColumns;
using testing::CliRun;
using testing::CountOccurrences;

const std::string kResources = std::string(SINEW_TEST_DATA_DIR) +
                               "/opensim-org/opensim-core/Applications/Analyze/tests/resources/";
const std::string kModel = kResources + "SinglePin.osim";
constexpr double kDeg = std::numbers::pi / 180;

class AngleUnitsTest : public testing::CliTest {
 protected:
  // Writes a table of r1_z values at t = 0, 1 under `header` (ending before endheader).
  std::string WriteTable(const std::string& name, const std::string& header, double q0,
                         double q1) const {
    std::ofstream out(Path(name));
    out.precision(17);
    out << header << "endheader\ntime\tr1_z\n0\t" << q0 << "\n1\t" << q1 << "\n";
    return Path(name);
  }
  // rod1's mass-centre x for each row of the table, from `sinew kinematics`.
  std::vector<double> Rod1X(const std::string& table, CliRun* run) const {
    *run = Run("kinematics " + kModel + " --motion " + table + " --out " + Path("out"));
    EXPECT_EQ(run->exit_code, 0) << run->err;
    return ReadStoColumns(Path("out/bodies.sto")).at("rod1_X");
  }
};

TEST_F(AngleUnitsTest, StoWithoutInDegreesIsRadiansAndDegreeLikeValuesAreFlagged) {
  const std::string table = WriteTable("degrees.sto", "pin\nversion=1\n", 30, 57.3);
  CliRun run;
  const std::vector<double> x = Rod1X(table, &run);
  ASSERT_EQ(x.size(), 2u);
  EXPECT_NEAR(x[0], 0.5 * std::sin(30.0), 1e-12);  // radians, as OpenSim reads it
  EXPECT_NEAR(x[1], 0.5 * std::sin(57.3), 1e-12);
  EXPECT_EQ(CountOccurrences(run.err, "sinew: warning:"), 1) << run.err;
  EXPECT_NE(run.err.find("sinew: warning: " + table +
                         ": no inDegrees line, so its angles are read as radians (as OpenSim "
                         "reads them), but 1 rotational column goes beyond 2*pi and looks like "
                         "degrees (r1_z). If they are degrees, add the line inDegrees=yes before "
                         "endheader\n"),
            std::string::npos)
      << run.err;
  // The same table through simulate's --initial-states: the same warning.
  const CliRun simulate = Run("simulate " + kModel + " --duration 0 --quiet --initial-states " +
                              table + " --out " + Path("sim"));
  EXPECT_EQ(simulate.exit_code, 0) << simulate.err;
  EXPECT_NE(simulate.err.find(table + ": no inDegrees line"), std::string::npos) << simulate.err;
}

TEST_F(AngleUnitsTest, OldMotWithoutInDegreesIsDegreesAsInOpenSim) {
  // No version line: OpenSim takes it for a SIMM motion, in degrees.
  const std::string table = WriteTable("old.mot", "pin\nnRows=2\nnColumns=2\n", 30, 57.3);
  CliRun run;
  const std::vector<double> x = Rod1X(table, &run);
  ASSERT_EQ(x.size(), 2u);
  EXPECT_NEAR(x[0], 0.5 * std::sin(30 * kDeg), 1e-12);
  EXPECT_NEAR(x[1], 0.5 * std::sin(57.3 * kDeg), 1e-12);
  EXPECT_EQ(run.err.find("warning"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("sinew: note: " + table +
                         ": no inDegrees line in an old-format .mot file (no version=1): its "
                         "angles are read as degrees, as OpenSim reads a SIMM motion\n"),
            std::string::npos)
      << run.err;
  // With version=1 the same file is radians (OpenSim's default); small angles raise nothing.
  const std::string current = WriteTable("current.mot", "pin\nversion=1\n", 0.2, 0.4);
  const std::vector<double> y = Rod1X(current, &run);
  ASSERT_EQ(y.size(), 2u);
  EXPECT_NEAR(y[1], 0.5 * std::sin(0.4), 1e-12);
  EXPECT_EQ(run.err, "");
}

TEST_F(AngleUnitsTest, OpenSimsOwnDegreesMotMatchesItsRadiansTwin) {
  // OpenSim wrote the same 3 s run as SinglePin_states.sto (radians, no inDegrees line) and
  // SinglePin_states_degrees.mot (degrees, no inDegrees line, no version).
  CliRun run;
  const std::vector<double> x = Rod1X(kResources + "SinglePin_states_degrees.mot", &run);
  const auto radians = ReadStoColumns(kResources + "SinglePin_states.sto");
  const std::vector<double>& q = radians.at("r1_z");
  ASSERT_EQ(x.size(), q.size());
  double worst = 0;
  for (size_t i = 0; i < q.size(); ++i)
    worst = std::max(worst, std::abs(x[i] - 0.5 * std::sin(q[i])));
  // Both files print 20 digits: they agree to rounding of the degree conversion.
  EXPECT_LT(worst, 1e-14);
  EXPECT_EQ(run.err.find("warning"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace sinew

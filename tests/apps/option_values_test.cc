// Number options that are not finite numbers (inf, nan, '', 1e400) or out of range, and runs
// whose size is absurd (--report-interval 1e-9, --step 1e-12), are refused before any work with
// exit code 2 and a message naming the option.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "apps/cli_test_util.h"

namespace sinew {
namespace {

using testing::CliRun;

const std::string kModel = std::string(SINEW_TEST_DATA_DIR) +
                           "/opensim-org/opensim-core/Applications/Analyze/tests/resources/"
                           "SinglePin.osim";

class OptionValuesTest : public testing::CliTest {
 protected:
  // Runs `sinew COMMAND MODEL ARGS` and expects exit code 2 with `message` on stderr.
  void ExpectRefused(const std::string& command, const std::string& args,
                     const std::string& message) const {
    const CliRun run = Run(command + " " + kModel + " " + args);
    EXPECT_EQ(run.exit_code, 2) << args << "\n" << run.err;
    EXPECT_NE(run.err.find("sinew: error: " + message), std::string::npos) << args << "\n"
                                                                           << run.err;
  }
  void ExpectSimulateRefused(const std::string& args, const std::string& message) const {
    ExpectRefused("simulate", args + " --out " + Path("out"), message);
    EXPECT_FALSE(std::filesystem::exists(dir() / "out" / "states.sto")) << args;
  }
};

TEST_F(OptionValuesTest, DurationMustBeAFiniteNumberAtLeastZero) {
  for (const char* value : {"inf", "-inf", "nan", "''", "-1", "1e400", "1s"}) {
    std::string shown = value;
    if (shown == "''") shown = "";
    ExpectSimulateRefused(std::string("--duration ") + value,
                          "--duration: expects a finite number >= 0, not '" + shown + "'");
  }
}

TEST_F(OptionValuesTest, StepIntervalAndAccuracyMustBeFinite) {
  ExpectSimulateRefused("--duration 1 --step nan",
                        "--step: expects a finite number >= 0, not 'nan'");
  ExpectSimulateRefused("--duration 1 --step -1e-3", "--step: expects a finite number >= 0");
  ExpectSimulateRefused("--duration 1 --report-interval inf",
                        "--report-interval: expects a finite number > 0, not 'inf'");
  ExpectSimulateRefused("--duration 1 --report-interval 0",
                        "--report-interval: expects a finite number > 0, not '0'");
  ExpectSimulateRefused("--duration 1 --accuracy nan",
                        "--accuracy: expects a finite number > 0, not 'nan'");
}

TEST_F(OptionValuesTest, AbsurdRunSizesAreRefusedUpFront) {
  ExpectSimulateRefused("--duration 1e300",
                        "--duration 1e+300 with --report-interval 0.01 asks for 1e+302 output "
                        "rows; at most 1e+08 are allowed");
  ExpectSimulateRefused("--duration 1 --report-interval 1e-9",
                        "--duration 1 with --report-interval 1e-09 asks for 1e+09 output rows");
  ExpectSimulateRefused("--duration 1 --integrator euler --step 1e-12",
                        "--duration 1 with --step 1e-12 asks for at least 1e+12 integration "
                        "steps; at most 1e+09 are allowed");
}

TEST_F(OptionValuesTest, RenderTimeAndExportFpsMustBeFinite) {
  ExpectRefused("render", "--time nan --out " + Path("x.png"),
                "--time: expects a finite number, not 'nan'");
  ExpectRefused("export", "--fps inf --out " + Path("x.glb"),
                "--fps: expects a finite number >= 0, not 'inf'");
}

TEST_F(OptionValuesTest, ExcitationValuesMustBeFinite) {
  // Before, nan ran into "equations of motion are singular ... without mass or inertia".
  const std::string model =
      std::string(SINEW_TEST_DATA_DIR) + "/projectchrono/chrono/data/opensim/torque-actuator.osim";
  for (const char* value : {"constant:nan", "constant:inf", "ramp:0,1e400", "sine:1,nan,0"}) {
    const CliRun run = Run("simulate " + model + " --duration 0.01 --excitation grav=" + value +
                           " --out " + Path("out"));
    EXPECT_EQ(run.exit_code, 2) << value << "\n" << run.err;
    EXPECT_NE(run.err.find("sinew: error: --excitation grav=" + std::string(value) + ": '"),
              std::string::npos)
        << run.err;
    EXPECT_NE(run.err.find("' is not a finite number"), std::string::npos) << run.err;
  }
}

TEST_F(OptionValuesTest, RenderRefusesAnImageTooLargeForMemoryUpFront) {
  ExpectRefused("render", "--width 8192 --height 8192 --out " + Path("big.png"),
                "render: a 8192 x 8192 image needs 7360 MiB of frame buffers");
  EXPECT_FALSE(std::filesystem::exists(dir() / "big.png"));
}

TEST_F(OptionValuesTest, AnOrdinaryRunIsAccepted) {
  const CliRun run =
      Run("simulate " + kModel + " --duration 0.02 --step 1e-3 --quiet --out " + Path("out"));
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(std::filesystem::exists(dir() / "out" / "states.sto"));
}

}  // namespace
}  // namespace sinew

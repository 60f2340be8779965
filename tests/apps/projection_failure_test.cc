// `sinew simulate` driven into a position projection failure: a fixed-step integrator given an
// absurd step on tests/data/sinew/constraints.osim (bodies on FreeJoints held by OpenSim's
// body constraints: a weld, a point, a point on a line, a constant distance). The first 10 s
// step moves the free bodies by ~g h^2 = 1 km, far beyond what the Newton projection can bring
// back onto those constraints. (The fixed-step schemes move bodies along the joint tree, so a
// model of joints alone stays on its joints at any step: only loops and constraints can fail.)
// The command must end with exit code 2 and a message saying what failed, when, and what to
// try, not abort.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <string>

namespace {

const std::string kModel = std::string(SINEW_TEST_DATA_DIR) + "/sinew/constraints.osim";

struct CliResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

CliResult RunCli(const std::string& arguments) {
  const std::string command = std::string(SINEW_CLI_PATH) + " " + arguments + " 2>&1";
  CliResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  char buffer[4096];
  size_t n;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) result.output.append(buffer, n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

std::string TempDir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("sinew_projection_test_" + name);
  std::filesystem::remove_all(dir);
  return dir.string();
}

TEST(SimulateProjectionFailureTest, AbsurdFixedStepEndsWithACleanError) {
  for (const std::string integrator : {"euler", "implicit-euler"}) {
    SCOPED_TRACE(integrator);
    const std::string out = TempDir(integrator);
    const CliResult result =
        RunCli("simulate " + kModel + " --duration 10 --integrator " + integrator +
               " --step 10 --report-interval 10 --quiet --out " + out);
    EXPECT_EQ(result.exit_code, 2) << result.output;
    const std::string& m = result.output;
    // What failed, in which step, how badly, and what to try.
    EXPECT_NE(m.find("sinew: error: integrator '" + integrator +
                     "': position projection failed in the step from t = 0 s to t = 10 s"),
              std::string::npos)
        << m;
    EXPECT_NE(m.find("largest constraint error is still"), std::string::npos) << m;
    EXPECT_NE(m.find("try a smaller step"), std::string::npos) << m;
    EXPECT_NE(m.find("rk45"), std::string::npos) << m;
    // Nothing half-written.
    EXPECT_FALSE(std::filesystem::exists(out + "/states.sto"));
  }
}

// The same model and integrator with an ordinary step simulate fine: the failure above is the
// step's, not the model's.
TEST(SimulateProjectionFailureTest, SameModelWithAnOrdinaryStepSimulates) {
  const std::string out = TempDir("ordinary");
  const CliResult result = RunCli(
      "simulate " + kModel + " --duration 0.1 --integrator euler --step 1e-3 --quiet --out " + out);
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_TRUE(std::filesystem::exists(out + "/states.sto"));
}

}  // namespace

// Command-line mistakes (unknown option, bad value, missing argument, no command) exit with
// code 2 and print CLI11's message, the usage line of the command and where to find help;
// --help and --version exit 0. The version and build type come from the CMake project, read
// here from the top-level CMakeLists.txt and the build's CMakeCache.txt.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>

#include "apps/cli_test_util.h"

namespace sinew {
namespace {

using testing::CliRun;

const std::string kModel = std::string(SINEW_TEST_DATA_DIR) +
                           "/opensim-org/opensim-core/Applications/Analyze/tests/resources/"
                           "SinglePin.osim";

class UsageTest : public testing::CliTest {
 protected:
  // Checks a usage error: exit code 2, nothing on stdout, and on stderr the message, the
  // usage line and the pointer to --help of `command` ("sinew simulate").
  void ExpectUsageError(const std::string& args, const std::string& message,
                        const std::string& command, const std::string& usage) const {
    const CliRun run = Run(args);
    EXPECT_EQ(run.exit_code, 2) << args << "\n" << run.err;
    EXPECT_EQ(run.out, "") << args;
    EXPECT_EQ(run.err, "sinew: error: " + message + "\n" + usage + "\nRun '" + command +
                           " --help' for more information.\n")
        << args;
  }
};

TEST_F(UsageTest, MistakesExitWithTwoAndTheUsage) {
  const std::string simulate_usage = "Usage: sinew simulate [OPTIONS] model";
  ExpectUsageError("simulate " + kModel + " --duration 1 --out " + Path("out") + " --bogus",
                   "The following argument was not expected: --bogus", "sinew simulate",
                   simulate_usage);
  ExpectUsageError("simulate " + kModel + " --duration abc --out " + Path("out"),
                   "--duration: expects a finite number >= 0, not 'abc'", "sinew simulate",
                   simulate_usage);
  ExpectUsageError("simulate " + kModel + " --out " + Path("out"), "--duration is required",
                   "sinew simulate", simulate_usage);
  ExpectUsageError("render " + kModel + " --vis shiny --out " + Path("x.png"),
                   "--vis: shiny not in {primitives,mesh,none}", "sinew render",
                   "Usage: sinew render [OPTIONS] model");
  ExpectUsageError("", "A subcommand is required", "sinew", "Usage: sinew [OPTIONS] SUBCOMMAND");
  ExpectUsageError("frobnicate",
                   "unknown command 'frobnicate' (the commands are inspect simulate forward "
                   "export render kinematics analyze)",
                   "sinew", "Usage: sinew [OPTIONS] SUBCOMMAND");
  ExpectUsageError("analyze " + kModel + " --out " + Path("out"), "--motion is required",
                   "sinew analyze", "Usage: sinew analyze [OPTIONS] model");
  EXPECT_FALSE(std::filesystem::exists(Path("out")));
}

TEST_F(UsageTest, HelpExitsWithZero) {
  const CliRun run = Run("simulate --help");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("Usage: "), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("--initial-states"), std::string::npos) << run.out;
  EXPECT_EQ(run.err, "");
}

TEST_F(UsageTest, VersionIsTheProjectVersionAndBuildType) {
  // The version in `project(sinew VERSION x.y.z ...)`.
  const std::string cmake_lists =
      testing::ReadText(std::filesystem::path(SINEW_TEST_DATA_DIR) / "../../CMakeLists.txt");
  std::smatch version;
  ASSERT_TRUE(std::regex_search(cmake_lists, version,
                                std::regex(R"(project\(sinew VERSION ([0-9][0-9.]*))")));
  // The build type in the CMakeCache.txt of the build that made the program.
  std::filesystem::path cache;
  for (std::filesystem::path dir = std::filesystem::path(SINEW_CLI_PATH).parent_path();
       !dir.empty() && dir != dir.root_path(); dir = dir.parent_path()) {
    if (std::filesystem::exists(dir / "CMakeCache.txt")) {
      cache = dir / "CMakeCache.txt";
      break;
    }
  }
  ASSERT_FALSE(cache.empty());
  std::smatch build_type;
  const std::string cache_text = testing::ReadText(cache);
  ASSERT_TRUE(std::regex_search(cache_text, build_type,
                                std::regex(R"(\nCMAKE_BUILD_TYPE:[A-Z]+=([^\n]*))")));
  const CliRun run = Run("--version");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "sinew " + version[1].str() + " (" + build_type[1].str() + " build)\n");
  EXPECT_EQ(run.err, "");
}

}  // namespace
}  // namespace sinew

// `sinew simulate` output: rows streamed to disk, the row count and status in the header, a
// clean stop on SIGINT that keeps the rows computed so far (marked partial), no temporary
// files left behind, and a symlink at an output name replaced, never followed.
#include <gtest/gtest.h>
#include <sinew/io/storage.h>
#include <sys/wait.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "apps/cli_test_util.h"

namespace sinew {
namespace {

const std::string kResources = std::string(SINEW_TEST_DATA_DIR) +
                               "/opensim-org/opensim-core/Applications/Analyze/tests/resources/";
const std::string kSinglePin = kResources + "SinglePin.osim";

using testing::CliTest;

// Temporary files (NAME.tmp.PID.N, see sinew::AtomicFile) left in `dir`.
int TemporaryFiles(const std::filesystem::path& dir) {
  int n = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().filename().string().find(".tmp.") != std::string::npos) ++n;
  }
  return n;
}

class SimulateOutputTest : public CliTest {};

TEST_F(SimulateOutputTest, CompleteRunSaysSoInItsHeader) {
  const auto run = Run("simulate " + kSinglePin + " --duration 1 --quiet --out " + Path("out"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const io::Storage states = io::ReadStorage(Path("out") + "/states.sto");
  EXPECT_EQ(states.NumRows(), 101);
  EXPECT_TRUE(states.notes.empty());  // nRows agrees with the rows present
  EXPECT_EQ(states.Metadata("status"), "complete");
  EXPECT_EQ(io::ReadStorage(Path("out") + "/bodies.sto").Metadata("status"), "complete");
  // SinglePin has no forces: forces.sto holds the time column alone, at the same rows.
  const io::Storage forces = io::ReadStorage(Path("out") + "/forces.sto");
  EXPECT_EQ(forces.NumRows(), 101);
  EXPECT_EQ(forces.NumColumns(), 0);
  EXPECT_EQ(forces.Metadata("status"), "complete");
  EXPECT_EQ(TemporaryFiles(Path("out")), 0);
}

TEST_F(SimulateOutputTest, InterruptKeepsTheRowsComputedSoFar) {
  // A run of 4 10^7 s (8 10^7 rows, under the CLI's limit of 10^8) cannot end in the 3 s before
  // SIGINT arrives (long enough for rows to be written on a loaded machine, even under sanitizers):
  // once swinging (many short steps), once at rest (rk45's steps grow huge, each holding many
  // report times: on an idle machine the 2 million rows of a 10^6 s run were all written within the
  // 3 s).
  const std::string swing = " --initial-states " + kResources + "SinglePin_InitialStates.sto";
  for (const std::string& start : {swing, std::string()}) {
    std::filesystem::remove_all(Path("out"));
    // --foreground: otherwise timeout also signals its own process group, so the CLI gets
    // SIGINT twice, and the second one (its handler resets, so that a second Ctrl-C kills) can
    // kill it before it has written its partial tables: the test failed now and then so.
    const std::string command = "timeout --foreground --preserve-status -s INT 3 " +
                                std::string(SINEW_CLI_PATH) + " simulate " + kSinglePin + start +
                                " --duration 4e7 --report-interval 0.5 --quiet --out " +
                                Path("out") + " 2>" + Path("err.txt");
    const int status = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(status)) << start;
    EXPECT_EQ(WEXITSTATUS(status), 128 + SIGINT) << start;
    const std::string err = testing::ReadText(Path("err.txt"));
    EXPECT_NE(err.find("stopped by SIGINT"), std::string::npos) << err;
    for (const char* name : {"/states.sto", "/bodies.sto", "/forces.sto"}) {
      const io::Storage table = io::ReadStorage(Path("out") + name);
      EXPECT_GT(table.NumRows(), 2) << name;
      EXPECT_TRUE(table.notes.empty()) << name;  // the header's nRows is the rows present
      EXPECT_EQ(table.Metadata("status").rfind("partial (stopped by SIGINT at t = ", 0), 0u)
          << table.Metadata("status");
      EXPECT_LT(table.time.back(), 4e7);
    }
    EXPECT_EQ(TemporaryFiles(Path("out")), 0);
  }
}

TEST_F(SimulateOutputTest, SymlinkAtAnOutputNameIsReplacedNotFollowed) {
  std::filesystem::create_directories(Path("out"));
  {
    std::ofstream outside(Path("outside.txt"));
    outside << "must stay\n";
  }
  std::filesystem::create_symlink(Path("outside.txt"), Path("out") + "/states.sto");
  const auto run = Run("simulate " + kSinglePin + " --duration 0.1 --quiet --out " + Path("out"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(testing::ReadText(Path("outside.txt")), "must stay\n");
  EXPECT_FALSE(std::filesystem::is_symlink(Path("out") + "/states.sto"));
  EXPECT_EQ(io::ReadStorage(Path("out") + "/states.sto").NumRows(), 11);
}

}  // namespace
}  // namespace sinew

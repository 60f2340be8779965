// Running the built `sinew` program (SINEW_CLI_PATH) from a test: exit code, stdout and stderr
// apart, and a fresh folder per test under ::testing::TempDir() (which honours TEST_TMPDIR and
// TMPDIR), removed when the test ends. Every test in tests/apps writes only there.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace sinew::testing {

/// What one run of the program gave.
struct CliRun {
  int exit_code = -1;  ///< -1 when the program did not exit normally (a crash)
  std::string out;     ///< stdout
  std::string err;     ///< stderr
};

/// The whole text of `path` ("" when it cannot be read).
inline std::string ReadText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Number of times `needle` occurs in `text`.
inline int CountOccurrences(const std::string& text, const std::string& needle) {
  int n = 0;
  for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
  return n;
}

/// A test with its own empty folder `dir()`, removed afterwards, and `Run` to call the program.
class CliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string("sinew_") + info->test_suite_name() + "_" + info->name();
    for (char& c : name) {
      if (c == '/') c = '_';  // parameterized tests are named Suite/Test/0
    }
    dir_ = std::filesystem::path(::testing::TempDir()) / (name + "_" + std::to_string(getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  /// The test's folder.
  const std::filesystem::path& dir() const { return dir_; }
  /// `name` inside the test's folder, as a string for command lines.
  std::string Path(const std::string& name) const { return (dir_ / name).string(); }

  /// A copy of `model` in the test's folder in which every WrapEllipsoid is a WrapTorus (a wrap
  /// type Sinew does not wrap over), for tests of what is said about unsupported wrap objects.
  std::string CopyWithTorusWraps(const std::string& model) const {
    std::string text = ReadText(model);
    const std::string from = "WrapEllipsoid", to = "WrapTorus";
    for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at)) {
      text.replace(at, from.size(), to);
      at += to.size();
    }
    const std::string copy = Path("with_tori.osim");
    std::ofstream(copy) << text;
    return copy;
  }

  /// Runs `sinew ARGS` with no mesh folders from the environment ($SINEW_GEOMETRY_PATH unset),
  /// capturing stdout and stderr in the test's folder.
  CliRun Run(const std::string& args) const {
    const std::filesystem::path out = dir_ / ".stdout", err = dir_ / ".stderr";
    const std::string command = "env -u SINEW_GEOMETRY_PATH " + std::string(SINEW_CLI_PATH) + " " +
                                args + " >" + out.string() + " 2>" + err.string();
    const int status = std::system(command.c_str());
    CliRun run;
    run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.out = ReadText(out);
    run.err = ReadText(err);
    return run;
  }

 private:
  std::filesystem::path dir_;
};

}  // namespace sinew::testing

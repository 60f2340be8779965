// WriteFileAtomically: a complete file or none, never through a symbolic link, nothing left
// behind when writing fails.
#include <gtest/gtest.h>
#include <sinew/common/atomic_file.h>
#include <sinew/common/error.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace sinew {
namespace {

namespace fs = std::filesystem;

class AtomicFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(::testing::TempDir()) /
           ("sinew_atomic_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
            std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  static std::string Read(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }
  // The number of entries in the test's folder (a left-over temporary would add one).
  int NumEntries() const {
    int n = 0;
    for ([[maybe_unused]] const fs::directory_entry& e : fs::directory_iterator(dir_)) ++n;
    return n;
  }

  fs::path dir_;
};

TEST_F(AtomicFileTest, WritesTheWholeContentAndLeavesNoTemporary) {
  const fs::path file = dir_ / "out.sto";
  WriteFileAtomically(file.string(), std::string_view("first"));
  WriteFileAtomically(file.string(), std::string_view("second, longer"));
  EXPECT_EQ(Read(file), "second, longer");
  EXPECT_EQ(NumEntries(), 1);
}

TEST_F(AtomicFileTest, ANameAsLongAsTheSystemAllowsIsWritten) {
  const fs::path file = dir_ / std::string(255, 'n');  // the temporary's name must stay shorter
  WriteFileAtomically(file.string(), std::string_view("long"));
  EXPECT_EQ(Read(file), "long");
  EXPECT_EQ(NumEntries(), 1);
}

TEST_F(AtomicFileTest, ReplacesASymbolicLinkInsteadOfFollowingIt) {
  const fs::path outside = dir_ / "outside.txt";
  WriteFileAtomically(outside.string(), std::string_view("precious"));
  const fs::path link = dir_ / "states.sto";
  fs::create_symlink(outside, link);
  WriteFileAtomically(link.string(), std::string_view("new states"));
  EXPECT_EQ(Read(outside), "precious");
  EXPECT_FALSE(fs::is_symlink(link));
  EXPECT_EQ(Read(link), "new states");
}

TEST_F(AtomicFileTest, AStreamFailureKeepsTheOldFileAndRemovesTheTemporary) {
  const fs::path file = dir_ / "bodies.sto";
  WriteFileAtomically(file.string(), std::string_view("complete old file"));
  try {
    WriteFileAtomically(file.string(), [](std::ostream& out) {
      out << "half of a file";
      out.setstate(std::ios::badbit);  // what a full disk does to the stream
    });
    FAIL() << "a failed stream must be an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(file.string() + ": cannot write the file"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(Read(file), "complete old file");
  EXPECT_EQ(NumEntries(), 1);
}

TEST_F(AtomicFileTest, AnExceptionFromTheWriterLeavesNoFile) {
  const fs::path file = dir_ / "scene.glb";
  EXPECT_THROW(WriteFileAtomically(file.string(),
                                   [](std::ostream& out) {
                                     out << "partial";
                                     throw std::runtime_error("interrupted");
                                   }),
               std::runtime_error);
  EXPECT_FALSE(fs::exists(file));
  EXPECT_EQ(NumEntries(), 0);
}

TEST_F(AtomicFileTest, AFolderThatDoesNotExistIsAnErrorNamingTheFile) {
  const fs::path file = dir_ / "missing" / "out.png";
  try {
    WriteFileAtomically(file.string(), std::string_view("png"));
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.where().file, file.string());
    EXPECT_NE(e.message().find("No such file or directory"), std::string::npos) << e.what();
  }
}

TEST_F(AtomicFileTest, ADirectoryInTheWayIsAnErrorAndLeavesNoTemporary) {
  fs::create_directories(dir_ / "states.sto");
  EXPECT_THROW(WriteFileAtomically((dir_ / "states.sto").string(), std::string_view("x")), Error);
  EXPECT_EQ(NumEntries(), 1);
}

TEST_F(AtomicFileTest, AFullDeviceFailsTheFlushThatIsChecked) {
  // The premise of the stream checks above: a full disk (here /dev/full, which answers every
  // write with ENOSPC) shows as a failed stream after flush, which WriteFileAtomically tests.
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  std::ofstream full("/dev/full", std::ios::binary);
  full << std::string(1 << 16, 'x');
  full.flush();
  EXPECT_FALSE(full.good());
}

}  // namespace
}  // namespace sinew

// StorageWriter: rows streamed to a temporary file, the header's row count and status written
// at the end, the file moved into place only when finished.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/io/storage.h>
#include <sinew/io/storage_writer.h>

#include <filesystem>
#include <string>
#include <vector>

namespace sinew::io {
namespace {

std::filesystem::path FreshDir(const std::string& name) {
  const auto dir = std::filesystem::path(::testing::TempDir()) / ("sinew_writer_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

size_t Entries(const std::filesystem::path& dir) {
  size_t n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++n;
  return n;
}

Storage Header() {
  Storage header;
  header.name = "states";
  header.labels = {"a", "b"};
  return header;
}

TEST(StorageWriterTest, RowsReadBackExactlyWithTheirCountAndStatus) {
  const auto dir = FreshDir("rows");
  const std::string file = (dir / "t.sto").string();
  {
    StorageWriter writer(file, Header());
    EXPECT_FALSE(std::filesystem::exists(file));  // not under its name until finished
    for (int i = 0; i < 1000; ++i) {
      const std::vector<double> row = {0.1 * i, 1.0 / (i + 3)};
      writer.AppendRow(0.01 * i, row);
    }
    writer.Finish();
  }
  const Storage read = ReadStorage(file);
  ASSERT_EQ(read.NumRows(), 1000);
  EXPECT_TRUE(read.notes.empty());  // nRows agrees with the data
  EXPECT_EQ(read.Metadata("status"), "complete");
  EXPECT_EQ(read.Value(999, 1), 1.0 / 1002);  // full precision
  EXPECT_EQ(read.time[500], 0.01 * 500);
  EXPECT_EQ(Entries(dir), 1u);  // no temporary file left
}

TEST(StorageWriterTest, PartialRunIsMarkedAndUnfinishedWriterLeavesNothing) {
  const auto dir = FreshDir("partial");
  const std::string file = (dir / "p.sto").string();
  {
    StorageWriter writer(file, Header());
    const std::vector<double> row = {1, 2};
    writer.AppendRow(0.0, row);
    writer.Finish("stopped by SIGINT at t = 0.5 s");
  }
  EXPECT_EQ(ReadStorage(file).Metadata("status"), "partial (stopped by SIGINT at t = 0.5 s)");
  const std::string never = (dir / "never.sto").string();
  {
    StorageWriter writer(never, Header());
    const std::vector<double> short_row = {1};
    EXPECT_THROW(writer.AppendRow(0.0, short_row), Error);
  }  // destroyed unfinished
  EXPECT_FALSE(std::filesystem::exists(never));
  EXPECT_EQ(Entries(dir), 1u);
}

TEST(StorageWriterTest, MissingFolderIsAnErrorNamingTheFile) {
  try {
    StorageWriter writer("/nonexistent_sinew_folder/x.sto", Header());
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent_sinew_folder/x.sto"), std::string::npos);
  }
}

}  // namespace
}  // namespace sinew::io

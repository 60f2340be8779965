// Regression tests for what fuzz_storage_reader found: a declared count too large for a count
// (nRows=1e300 was converted to long: undefined behaviour) and a table whose only column is a
// time label with a space in it (written without a tab, it was read back as several columns).
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/io/storage.h>

#include <string>

namespace sinew {
namespace {

TEST(StorageLimitsTest, CountsThatAreNotCountsAreErrorsWithTheLine) {
  for (const std::string bad :
       {"nRows=1e300", "nColumns=1e19", "nRows=nan", "nRows=-inf", "nColumns=-1"}) {
    const std::string text = "name\n" + bad + "\nendheader\ntime\n0\n";
    try {
      io::ParseStorage(text, "bad.sto");
      ADD_FAILURE() << "no error for " << bad;
    } catch (const Error& e) {
      EXPECT_EQ(e.where().line, 2) << e.what();
      EXPECT_NE(std::string(e.what()).find("expects a count"), std::string::npos) << e.what();
    }
  }
  // A large but plausible count that disagrees with the data is only a note, as before.
  const io::Storage s = io::ParseStorage("name\nnRows=1e9\nendheader\ntime\n0\n", "ok.sto");
  EXPECT_EQ(s.NumRows(), 1);
  ASSERT_EQ(s.notes.size(), 1u);
  EXPECT_NE(s.notes[0].message.find("nRows=1000000000 but the file has 1 rows"), std::string::npos)
      << s.notes[0].message;
}

TEST(StorageLimitsTest, LoneTimeLabelWithABlankRoundTrips) {
  io::Storage s;
  s.time_label = "time (s)";
  s.AppendRow(0.0, {});
  s.AppendRow(0.5, {});
  const io::Storage back = io::ParseStorage(io::FormatStorage(s), "memory");
  EXPECT_EQ(back.time_label, "time (s)");
  EXPECT_EQ(back.NumColumns(), 0);
  EXPECT_EQ(back.time, s.time);
  // With data columns the label line has tabs already and gets no extra one.
  s = io::Storage();
  s.time_label = "time (s)";
  s.labels = {"a b"};
  s.AppendRow(0.0, {1.0});
  const std::string text = io::FormatStorage(s);
  EXPECT_NE(text.find("\ntime (s)\ta b\n"), std::string::npos) << text;
  EXPECT_EQ(io::ParseStorage(text, "memory").labels, s.labels);
}

}  // namespace
}  // namespace sinew

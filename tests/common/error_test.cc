#include <gtest/gtest.h>
#include <sinew/common/error.h>

namespace sinew {
namespace {

TEST(ErrorTest, FormatsFileLineComponentAndMessage) {
  Error e(SourceLocation{"model.osim", 214}, "/jointset/knee_r", "unknown parent frame");
  EXPECT_STREQ(e.what(), "model.osim:214: /jointset/knee_r: unknown parent frame");
  EXPECT_EQ(e.where().line, 214);
  EXPECT_EQ(e.component(), "/jointset/knee_r");
}

TEST(ErrorTest, LeavesOutUnknownParts) {
  EXPECT_EQ(FormatMessage({"a.osim", 0}, "", "x"), "a.osim: x");
  EXPECT_EQ(FormatMessage({}, "/bodyset/b", "x"), "/bodyset/b: x");
  EXPECT_STREQ(Error("plain").what(), "plain");
}

}  // namespace
}  // namespace sinew

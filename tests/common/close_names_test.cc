// FindCloseNames: the candidates offered by "no X named N; close names: ..." messages.
#include <gtest/gtest.h>
#include <sinew/common/text.h>

#include <string>
#include <vector>

namespace sinew {
namespace {

TEST(CloseNamesTest, TyposAndPartsAreCloseNearestFirst) {
  const std::vector<std::string> names = {"block_spring", "arm_spring", "arm_limit", "ground"};
  // One letter missing (distance 1), then a candidate two edits away.
  EXPECT_EQ(FindCloseNames("arm_sprin", names), (std::vector<std::string>{"arm_spring"}));
  EXPECT_EQ(FindCloseNames("Block_Spring", names), (std::vector<std::string>{"block_spring"}));
  // A part of a name is close whatever the distance.
  EXPECT_EQ(FindCloseNames("spring", names),
            (std::vector<std::string>{"arm_spring", "block_spring"}));
  EXPECT_TRUE(FindCloseNames("biceps", names).empty());
  EXPECT_EQ(FindCloseNames("arm", names, 1).size(), 1u);
}

}  // namespace
}  // namespace sinew

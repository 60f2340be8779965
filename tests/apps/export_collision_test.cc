// `sinew export --collision` and `sinew render --collision`: the collision shapes drawn as
// `simulate --collision --export` draws them (nodes whose source is "collision").
#include <gtest/gtest.h>
#include <sinew/viz/image.h>

#include <nlohmann/json.hpp>
#include <string>

#include "apps/cli_test_util.h"
#include "viz/glb_test_util.h"

namespace sinew {
namespace {

using testing::CliRun;

const std::string kData = SINEW_TEST_DATA_DIR;

class ExportCollisionTest : public testing::CliTest {
 protected:
  // The glb nodes drawn from collision shapes.
  int CollisionNodes(const std::string& glb_file) const {
    const viz::testing::ParsedGlb glb = viz::testing::ParseGlb(viz::ReadFileBytes(glb_file));
    int n = 0;
    for (const auto& node : glb.doc["nodes"]) {
      if (node.contains("extras") && node["extras"].contains("source") &&
          node["extras"]["source"] == "collision")
        ++n;
    }
    return n;
  }
};

TEST_F(ExportCollisionTest, ExportDrawsTheCollisionShapesOnlyWhenAsked) {
  // ball_on_floor.osim: its ContactSphere and ContactHalfSpace collide (no segment is long
  // enough for a seed cylinder: the free joint is at the ball's origin).
  const std::string ball = kData + "/sinew/ball_on_floor.osim";
  CliRun run = Run("export " + ball + " --vis primitives --collision --out " + Path("c.glb"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(CollisionNodes(Path("c.glb")), 2);
  run = Run("export " + ball + " --vis primitives --out " + Path("plain.glb"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(CollisionNodes(Path("plain.glb")), 0);
}

TEST_F(ExportCollisionTest, RenderDrawsTheCollisionShapesOnlyWhenAsked) {
  // reach.osim's segments get the seed's cylinders, in the contact colour: the picture changes.
  const std::string reach = kData + "/sinew/reach.osim";
  CliRun run = Run("render " + reach + " --vis primitives --collision --width 200 --height 200 " +
                   "--out " + Path("c.png"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  run = Run("render " + reach + " --vis primitives --width 200 --height 200 --out " +
            Path("plain.png"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(viz::ReadFileBytes(Path("c.png")), viz::ReadFileBytes(Path("plain.png")));
}

}  // namespace
}  // namespace sinew

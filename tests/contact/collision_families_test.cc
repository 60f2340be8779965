// The seed's collision families (OpenSimParser::EnableCollision): bodies at odd tree depth get
// family 1, at even depth family 2, and only bodies of one family collide. So a body never
// collides with its parent (or child), does collide with its siblings and its grandparent, and
// also never with any body whose depth differs by an odd number (an uncle and his nephew, a
// great-grandparent): the exclusion is wider than "not the parent" (docs/contact.md).
#include <gtest/gtest.h>
#include <sinew/contact/collision_model.h>
#include <sinew/opensim/parser.h>

#include <string>

namespace sinew::contact {
namespace {

TEST(CollisionFamiliesTest, SiblingsAndGrandparentsCollideParentsNever) {
  opensim::OpenSimParser parser;
  parser.EnableCollision(1, 2);
  parser.Parse(std::string(SINEW_TEST_DATA_DIR) +
               "/projectchrono/chrono/data/opensim/Rajagopal2015.osim");
  const CollisionModel& collision = parser.GetCollisionModel();
  const model::ModelSpec& spec = parser.GetSpec();
  auto body = [&](const char* name) {
    const int b = spec.FindBody(name);
    EXPECT_NE(b, model::kNone) << name;
    return b;
  };
  for (const model::JointSpec& j : spec.joints) {
    EXPECT_FALSE(collision.CanCollide(j.parent_body, j.child_body)) << j.name;
  }
  EXPECT_TRUE(collision.CanCollide(body("femur_r"), body("femur_l")));  // siblings
  EXPECT_TRUE(collision.CanCollide(body("pelvis"), body("tibia_r")));   // grandparent
  EXPECT_TRUE(collision.CanCollide(body("tibia_r"), body("tibia_l")));  // cousins
  EXPECT_FALSE(collision.CanCollide(body("femur_l"), body("tibia_r")));  // uncle and nephew
}

}  // namespace
}  // namespace sinew::contact

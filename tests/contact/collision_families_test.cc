// The seed's collision filter (OpenSimParser::EnableCollision): no collision between a body and
// its parent; every other pair may collide, siblings, grandparents, uncles and nephews
// included. The families still alternate with tree depth (the seed's API), but filtering is
// per pair (docs/contact.md).
#include <gtest/gtest.h>
#include <sinew/contact/collision_detection.h>
#include <sinew/contact/collision_model.h>
#include <sinew/opensim/parser.h>

#include <algorithm>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace sinew::contact {
namespace {

// The seed's Rajagopal2015 parsed with the seed's EnableCollision(1, 2).
class CollisionFamiliesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    parser.EnableCollision(1, 2);
    parser.Parse(std::string(SINEW_TEST_DATA_DIR) +
                 "/projectchrono/chrono/data/opensim/Rajagopal2015.osim");
  }
  opensim::OpenSimParser parser;
};

TEST_F(CollisionFamiliesTest, SiblingsAndGrandparentsCollideParentsNever) {
  const CollisionModel& collision = parser.GetCollisionModel();
  const model::ModelSpec& spec = parser.GetSpec();
  auto body = [&](const char* name) {
    const int b = spec.FindBody(name);
    EXPECT_NE(b, model::kNone) << name;
    return b;
  };
  // Ground's shapes are the environment (a floor), which touches every body, its child
  // included; between moving bodies a joint's parent and child never touch.
  for (const model::JointSpec& j : spec.joints) {
    if (j.parent_body == model::kGroundIndex) continue;
    EXPECT_FALSE(collision.CanCollide(j.parent_body, j.child_body)) << j.name;
  }
  EXPECT_TRUE(collision.CanCollide(model::kGroundIndex, body("pelvis")));
  EXPECT_TRUE(collision.CanCollide(body("femur_r"), body("femur_l")));  // siblings
  EXPECT_TRUE(collision.CanCollide(body("pelvis"), body("tibia_r")));   // grandparent
  EXPECT_TRUE(collision.CanCollide(body("tibia_r"), body("tibia_l")));  // cousins
  EXPECT_TRUE(collision.CanCollide(body("femur_l"), body("tibia_r")));  // uncle and nephew
  EXPECT_TRUE(collision.CanCollide(body("pelvis"), body("talus_r")));   // great-grandparent
  EXPECT_TRUE(collision.CanCollide(body("torso"), body("femur_r")));    // siblings
  // The families are the seed's: alternating with depth.
  for (const model::JointSpec& j : spec.joints) {
    if (j.parent_body == model::kGroundIndex)
      EXPECT_EQ(collision.family[j.child_body], 1);
    else
      EXPECT_NE(collision.family[j.parent_body], collision.family[j.child_body]) << j.name;
  }
}

// One cylinder per distinct joint point of a body: Rajagopal2015's femur holds its knee and
// its patella's joint at one point, which the seed's parser gives two identical cylinders
// (each femur contact then came twice: twice the Hertz force in SMC, a repeated row of W in NSC).
TEST_F(CollisionFamiliesTest, TwoJointsAtOnePointOfABodyGiveOneCylinder) {
  const CollisionModel& collision = parser.GetCollisionModel();
  const model::ModelSpec& spec = parser.GetSpec();
  // Every joint end on a moving body, 1 mm or more from its origin, is the end of exactly one
  // of that body's cylinders, and every cylinder is such an end.
  std::set<std::pair<int, std::vector<double>>> ends;
  for (const model::JointSpec& j : spec.joints) {
    for (const auto& [b, p] :
         {std::pair{j.parent_body, j.X_PF.p}, std::pair{j.child_body, j.X_BM.p}}) {
      if (b != model::kGroundIndex && p.norm() >= 1e-3) ends.insert({b, {p.x(), p.y(), p.z()}});
    }
  }
  std::set<std::pair<int, std::vector<double>>> cylinders;
  for (const CollisionCylinder& c : collision.shapes) {
    EXPECT_TRUE(c.p_B_start.isZero());
    cylinders.insert({c.body, {c.p_B_end.x(), c.p_B_end.y(), c.p_B_end.z()}});
  }
  EXPECT_EQ(cylinders.size(), collision.shapes.size());  // no two alike
  EXPECT_EQ(cylinders, ends);
  // The femurs: the knee and the patella at one point, one cylinder each.
  for (const char* femur : {"femur_r", "femur_l"}) {
    const int b = spec.FindBody(femur);
    EXPECT_EQ(std::count_if(collision.shapes.begin(), collision.shapes.end(),
                            [&](const CollisionCylinder& c) { return c.body == b; }),
              1)
        << femur;
    EXPECT_EQ(std::count_if(spec.joints.begin(), spec.joints.end(),
                            [&](const model::JointSpec& j) { return j.parent_body == b; }),
              2)
        << femur;
  }
}

// All shapes in one place, so that every pair the filter allows touches: a body touches its
// sibling, its grandparent and its uncle, never its parent or child.
TEST_F(CollisionFamiliesTest, BodyTouchesGrandparentAndSiblingsNeverItsParent) {
  // ground -> 1 -> 2 -> 3, and 4 a second child of 1 (2's sibling, 3's uncle).
  CollisionModel model;
  model.family = {0, 1, 2, 1, 2};
  model.jointed = {{0, 1}, {1, 2}, {2, 3}, {1, 4}};
  for (int b = 1; b <= 4; ++b) model.shapes.push_back({b, Vec3(-0.5, 0, 0), Vec3(0.5, 0, 0), 0.05});
  const CollisionDetector detector(model, std::nullopt);
  const std::vector<Transform> X_GB(5, Transform());
  std::set<std::pair<int, int>> touching;
  detector.FindContacts(X_GB, [&](const CollisionContact& c) {
    touching.insert({std::min(c.body1, c.body2), std::max(c.body1, c.body2)});
  });
  const std::set<std::pair<int, int>> expected = {
      {1, 3} /* grandparent */, {2, 4} /* siblings */, {3, 4} /* uncle */};
  EXPECT_EQ(touching, expected);
}

}  // namespace
}  // namespace sinew::contact

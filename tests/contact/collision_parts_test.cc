// The collision shapes drawn in the contact colour (opensim::CollisionPartsOf,
// viz::AddCollisionParts): the ball model's ContactSphere and floor, Rajagopal2015's cylinders.
#include <gtest/gtest.h>
#include <sinew/io/osim_reader.h>
#include <sinew/opensim/collision_parts.h>
#include <sinew/opensim/parser.h>

#include <string>

namespace sinew::contact {
namespace {

int CountCollisionParts(const viz::VisualBody& body) {
  int n = 0;
  for (const viz::VisualPart& p : body.parts) n += p.source == "collision" ? 1 : 0;
  return n;
}

TEST(CollisionPartsTest, BallAndFloorAreDrawnInTheContactColour) {
  const std::string file = std::string(SINEW_TEST_DATA_DIR) + "/sinew/ball_on_floor.osim";
  opensim::OpenSimParser parser;
  parser.EnableCollision();
  parser.Parse(file);
  viz::VisualScene scene = viz::BuildVisualScene(parser.GetSpec(), {viz::VisType::kPrimitives, {}});
  viz::AddCollisionParts(opensim::CollisionPartsOf(parser.GetCollisionModel()), scene);
  ASSERT_EQ(scene.bodies.size(), 2u);
  ASSERT_EQ(CountCollisionParts(scene.bodies[0]), 1);  // the floor's slab
  ASSERT_EQ(CountCollisionParts(scene.bodies[1]), 1);  // the sphere
  const viz::VisualPart& sphere = scene.bodies[1].parts.back();
  EXPECT_EQ(sphere.color, viz::kContactColor);
  EXPECT_EQ(sphere.scale, Vec3::Constant(0.1));
  // The slab lies inside the floor's solid (y < 0): its centre below y = 0.
  EXPECT_LT((scene.bodies[0].parts.back().X_BG.p).y(), 0.0);
}

TEST(CollisionPartsTest, SkeletonCylindersAreDrawnOnTheirBodies) {
  opensim::OpenSimParser parser;
  parser.EnableCollision();
  parser.Parse(std::string(SINEW_TEST_DATA_DIR) +
               "/projectchrono/chrono/data/opensim/Rajagopal2015.osim");
  const CollisionModel& model = parser.GetCollisionModel();
  viz::VisualScene scene = viz::BuildVisualScene(parser.GetSpec(), {viz::VisType::kPrimitives, {}});
  viz::AddCollisionParts(opensim::CollisionPartsOf(model), scene);
  int drawn = 0;
  for (const viz::VisualBody& b : scene.bodies) drawn += CountCollisionParts(b);
  EXPECT_EQ(drawn, static_cast<int>(model.shapes.size()));
}

}  // namespace
}  // namespace sinew::contact

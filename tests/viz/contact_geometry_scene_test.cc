// Contact geometry is drawn (primitives and mesh modes) in a colour of its own: the bouncing
// balls' sphere, mesh and floor are in the scene where the model puts them.
#include <gtest/gtest.h>
#include <sinew/io/osim_reader.h>
#include <sinew/viz/visual_scene.h>

#include <string>

namespace sinew::viz {
namespace {

const std::string kTests =
    std::string(SINEW_TEST_DATA_DIR) + "/opensim-org/opensim-core/OpenSim/Simulation/Test/";

// The parts of `scene` drawn in the contact colour, as (body name, source).
std::vector<std::pair<std::string, const VisualPart*>> ContactParts(const VisualScene& scene) {
  std::vector<std::pair<std::string, const VisualPart*>> out;
  for (const VisualBody& b : scene.bodies) {
    for (const VisualPart& p : b.parts) {
      if (p.color == kContactColor) out.emplace_back(b.name, &p);
    }
  }
  return out;
}

TEST(ContactGeometrySceneTest, BouncingBallsShowTheirSphereMeshAndFloor) {
  const model::ModelSpec ball = io::ReadOsim(kTests + "BouncingBall_HuntCrossley.osim");
  VisualOptions options;
  options.mode = VisType::kPrimitives;
  const VisualScene scene = BuildVisualScene(ball, options);
  const auto parts = ContactParts(scene);
  ASSERT_EQ(parts.size(), 2u);
  // The floor on ground: a slab just inside the solid (x > 0 of a frame turned -90 degrees
  // about z, so y < 0 in ground), its face on y = 0.
  EXPECT_EQ(parts[0].first, "ground");
  EXPECT_EQ(parts[0].second->source, "ContactHalfSpace");
  const Transform& X_GS = parts[0].second->X_BG;
  EXPECT_NEAR((X_GS.p - parts[0].second->scale.x() * X_GS.R.col(0)).y(), 0.0, 1e-12);
  EXPECT_LT(X_GS.p.y(), 0.0);
  // The 0.5 m sphere on the ball.
  EXPECT_EQ(parts[1].first, "ball");
  EXPECT_EQ(parts[1].second->source, "ContactSphere");
  EXPECT_EQ(parts[1].second->scale, Vec3::Constant(0.5));
  // Nothing is drawn without visualization.
  options.mode = VisType::kNone;
  EXPECT_TRUE(ContactParts(BuildVisualScene(ball, options)).empty());
  // BouncingBallModelEF.osim: its ContactMesh is read from sphere.obj beside the model.
  options.mode = VisType::kMesh;
  const VisualScene mesh_scene =
      BuildVisualScene(io::ReadOsim(kTests + "BouncingBallModelEF.osim"), options);
  const auto mesh_parts = ContactParts(mesh_scene);
  ASSERT_EQ(mesh_parts.size(), 2u);
  EXPECT_EQ(mesh_parts[1].second->source, "sphere.obj");
  EXPECT_EQ(mesh_parts[1].second->mesh->triangles.size(), 720u);
}

}  // namespace
}  // namespace sinew::viz

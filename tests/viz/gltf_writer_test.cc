// The .glb written for a small hand-made model: container layout, node/mesh structure,
// accessor bounds and the animation samples, all read back with nlohmann-json.
#include <gtest/gtest.h>
#include <sinew/kinematics/body_depths.h>
#include <sinew/math/rotation.h>
#include <sinew/viz/export_animation.h>
#include <sinew/viz/gltf_writer.h>

#include <cmath>

#include "viz/glb_test_util.h"
#include "viz/two_link_spec.h"

namespace sinew::viz {
namespace {

VisualOptions MeshOptions() {
  VisualOptions options;
  options.mode = VisType::kMesh;
  options.geometry_dirs = {testing::kDataDir + "/opensim-org/opensim-models/Geometry"};
  return options;
}

TEST(VisualSceneTest, MeshModeReadsMeshesAndFallsBackWithAWarning) {
  const model::ModelSpec spec = testing::TwoLinkSpec();
  VisualScene scene = BuildVisualScene(spec, MeshOptions());
  ASSERT_EQ(scene.bodies.size(), 3u);
  EXPECT_TRUE(scene.bodies[0].parts.empty());
  ASSERT_EQ(scene.bodies[1].parts.size(), 2u);
  EXPECT_EQ(scene.bodies[1].parts[0].mesh->triangles.size(), 140u);
  EXPECT_EQ(scene.bodies[1].parts[0].scale, Vec3(2, 2, 2));
  EXPECT_EQ(scene.bodies[1].parts[1].scale, Vec3::Constant(0.1));  // unit sphere * radius
  // The missing mesh: one warning naming the file and every folder searched; primitives.
  ASSERT_EQ(scene.warnings.size(), 1u);
  const std::string warning = scene.warnings[0].Format();
  EXPECT_NE(warning.find("not_there.vtp"), std::string::npos) << warning;
  EXPECT_NE(warning.find("opensim-org/opensim-models/Geometry"), std::string::npos) << warning;
  EXPECT_NE(warning.find("/bodyset/tip/lost"), std::string::npos) << warning;
  ASSERT_FALSE(scene.bodies[2].parts.empty());
  EXPECT_EQ(scene.bodies[2].parts[0].source, "primitive");
  // OpenSim's placeholder "Unassigned" means no file: nothing drawn, nothing to warn about.
  model::ModelSpec placeholder = testing::TwoLinkSpec();
  placeholder.bodies[2].geometry[0].mesh_file = "Unassigned";
  scene = BuildVisualScene(placeholder, MeshOptions());
  EXPECT_TRUE(scene.warnings.empty());
  EXPECT_TRUE(scene.bodies[2].parts.empty());
}

TEST(VisualSceneTest, ArrowsAndLinesBecomeCylindersAndCones) {
  model::ModelSpec spec = testing::TwoLinkSpec();
  model::GeometrySpec arrow;
  arrow.name = "arrow";
  arrow.type = "Arrow";
  arrow.dimensions = {{"start_point", {0, 0, 0}}, {"direction", {2, 0, 0}}, {"length", {1}}};
  model::GeometrySpec line;
  line.name = "line";
  line.type = "Line";
  line.dimensions = {{"start_point", {0, 1, 0}}, {"end_point", {0, 1, 3}}};
  spec.bodies[0].geometry = {arrow, line};
  VisualScene scene = BuildVisualScene(spec, MeshOptions());
  const auto& parts = scene.bodies[0].parts;
  ASSERT_EQ(parts.size(), 3u);  // shaft + head, line
  auto end_of = [](const VisualPart& p, double y) { return p.X_BG * Vec3(0, y * p.scale.y(), 0); };
  // The shaft runs from the start point to the head (85% of the length), the cone's apex
  // (unit cone y = 1) at the arrow's tip.
  EXPECT_LT(end_of(parts[0], -1).norm(), 1e-12);
  EXPECT_LT((end_of(parts[0], 1) - Vec3(0.85, 0, 0)).norm(), 1e-12);
  EXPECT_LT((end_of(parts[1], 1) - Vec3(1, 0, 0)).norm(), 1e-12);
  EXPECT_LT((end_of(parts[2], -1) - Vec3(0, 1, 0)).norm(), 1e-12);
  EXPECT_LT((end_of(parts[2], 1) - Vec3(0, 1, 3)).norm(), 1e-12);
}

TEST(VisualSceneTest, PrimitivesLinkEachBodyFrameToItsJointsColouredByDepth) {
  const model::ModelSpec spec = testing::TwoLinkSpec();
  EXPECT_EQ(kinematics::CalcBodyDepths(spec), (std::vector<int>{0, 1, 2}));
  VisualOptions options;
  options.mode = VisType::kPrimitives;
  VisualScene scene = BuildVisualScene(spec, options);
  EXPECT_TRUE(scene.warnings.empty());
  // link: sphere + cylinder to the pin (0, 0.5, 0) + cylinder to the weld (0, -0.5, 0).
  const auto& parts = scene.bodies[1].parts;
  ASSERT_EQ(parts.size(), 3u);
  // The cylinder's ends (unit cylinder y = +-1) land on the body origin and the joint.
  const VisualPart& c = parts[1];
  const Vec3 top = c.X_BG * Vec3(0, c.scale.y(), 0), bottom = c.X_BG * Vec3(0, -c.scale.y(), 0);
  EXPECT_LT((top - Vec3(0, 0.5, 0)).norm(), 1e-12);
  EXPECT_LT(bottom.norm(), 1e-12);
  // Green at the root, red at the leaf.
  const Vec3 root = scene.bodies[0].parts[0].color, leaf = scene.bodies[2].parts[0].color;
  EXPECT_GT(root.y(), root.x());
  EXPECT_GT(leaf.x(), leaf.y());
  VisualOptions none;
  none.mode = VisType::kNone;
  for (const auto& b : BuildVisualScene(spec, none).bodies) EXPECT_TRUE(b.parts.empty());
  EXPECT_THROW(ParseVisType("wireframe"), Error);
}

TEST(GltfWriterTest, WritesAValidAnimatedGlb) {
  const model::ModelSpec spec = testing::TwoLinkSpec();
  VisualScene scene = BuildVisualScene(spec, MeshOptions());
  // Three frames of a swinging pendulum: link rotates about z by 0, 0.4, 0.8 rad.
  const BodyMotion motion = testing::SwingMotion(3, 1.0, 0.5, 0.4);
  testing::ParsedGlb glb = testing::ParseGlb(WriteGlb(scene, motion, "two_link"));
  const auto& doc = glb.doc;
  EXPECT_EQ(doc["asset"]["version"], "2.0");
  size_t parts = 0;
  for (const auto& b : scene.bodies) parts += b.parts.size();
  EXPECT_EQ(doc["nodes"].size(), 1 + scene.bodies.size() + parts);
  EXPECT_EQ(doc["meshes"].size(), parts);
  ASSERT_EQ(doc["buffers"].size(), 1u);
  EXPECT_EQ(doc["buffers"][0]["byteLength"], glb.bin.size());
  // The scene root holds one node per body, named after it.
  const auto& root = doc["nodes"][doc["scenes"][0]["nodes"][0].get<int>()];
  ASSERT_EQ(root["children"].size(), 3u);
  EXPECT_EQ(doc["nodes"][root["children"][2].get<int>()]["name"], "tip");
  // POSITION accessors carry min/max that bound their data.
  for (const auto& mesh : doc["meshes"]) {
    const int a = mesh["primitives"][0]["attributes"]["POSITION"];
    const auto& accessor = doc["accessors"][a];
    ASSERT_TRUE(accessor.contains("min") && accessor.contains("max"));
    std::vector<float> v = testing::ReadFloatAccessor(glb, a);
    for (size_t i = 0; i < v.size(); ++i) {
      EXPECT_GE(v[i], accessor["min"][i % 3].get<float>());
      EXPECT_LE(v[i], accessor["max"][i % 3].get<float>());
    }
  }
  // The animation: times from 0, and the tip's translation sampled per frame.
  ASSERT_EQ(doc["animations"].size(), 1u);
  const auto& anim = doc["animations"][0];
  EXPECT_EQ(anim["channels"].size(), 6u);  // 3 bodies x (translation, rotation)
  EXPECT_DOUBLE_EQ(anim["extras"]["start_time"].get<double>(), 1.0);
  const int tip_node = root["children"][2];
  for (const auto& channel : anim["channels"]) {
    if (channel["target"]["node"] != tip_node) continue;
    const auto& sampler = anim["samplers"][channel["sampler"].get<int>()];
    EXPECT_EQ(testing::ReadFloatAccessor(glb, sampler["input"]),
              (std::vector<float>{0.0f, 0.5f, 1.0f}));
    std::vector<float> out = testing::ReadFloatAccessor(glb, sampler["output"]);
    if (channel["target"]["path"] == "translation") {
      // Tip at distance 1 below the pivot, rotated by 0.8 rad at the last frame.
      EXPECT_NEAR(out[6], std::sin(0.8), 1e-6);
      EXPECT_NEAR(out[7], -std::cos(0.8), 1e-6);
    } else {
      ASSERT_EQ(out.size(), 12u);  // quaternion xyzw about z: (0, 0, sin(a/2), cos(a/2))
      EXPECT_NEAR(out[10], std::sin(0.4), 1e-6);
      EXPECT_NEAR(out[11], std::cos(0.4), 1e-6);
    }
  }
}

TEST(GltfWriterTest, StaticSceneHasNoAnimationAndEmptySceneStaysValid) {
  const model::ModelSpec spec = testing::TwoLinkSpec();
  VisualScene scene = BuildVisualScene(spec, MeshOptions());
  testing::ParsedGlb glb = testing::ParseGlb(WriteGlb(scene, {}, "static"));
  EXPECT_FALSE(glb.doc.contains("animations"));
  VisualOptions none;
  none.mode = VisType::kNone;
  testing::ParsedGlb empty = testing::ParseGlb(WriteGlb(BuildVisualScene(spec, none), {}, "e"));
  EXPECT_FALSE(empty.doc.contains("meshes"));
  EXPECT_FALSE(empty.doc.contains("buffers"));
  EXPECT_EQ(empty.doc["nodes"].size(), 4u);
}

TEST(ExportAnimationTest, ThinMotionKeepsEndsAndRespectsTheFrameRate) {
  // 101 frames 0.01 s apart (100 fps) thinned to 30 fps: a frame is kept once 1/30 s has
  // passed since the last kept one, i.e. every 4th (0.04 s): k = 0, 4, ..., 100, 26 frames,
  // and the last frame (k = 100) is among them.
  const BodyMotion motion = testing::SwingMotion(101, 0.0, 0.01, 0.01);
  const BodyMotion thin = ThinMotion(motion, 30);
  ASSERT_EQ(thin.times.size(), 26u);
  EXPECT_DOUBLE_EQ(thin.times.front(), 0.0);
  EXPECT_DOUBLE_EQ(thin.times.back(), 1.0);
  for (size_t k = 1; k + 1 < thin.times.size(); ++k) {
    EXPECT_NEAR(thin.times[k] - thin.times[k - 1], 0.04, 1e-12);
  }
  EXPECT_EQ(ThinMotion(motion, 0).times.size(), 101u);
  EXPECT_EQ(ThinMotion(motion, 1000).times.size(), 101u);
}

}  // namespace
}  // namespace sinew::viz

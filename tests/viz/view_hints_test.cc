// The viewer's hints (docs/contact.md, "Seeing it"): the floor is the model's ContactHalfSpace on
// ground (or y = 0), carried into the glTF scene's extras and the HTML page; the grid covers the
// motion; the camera follows a body that moves far; contact arrows come from a contacts table.
#include <gtest/gtest.h>
#include <sinew/io/mesh_base64.h>
#include <sinew/io/osim_reader.h>
#include <sinew/viz/export_animation.h>
#include <sinew/viz/gltf_writer.h>
#include <sinew/viz/image.h>
#include <sinew/viz/motion_poses.h>
#include <sinew/viz/primitive_shapes.h>
#include <sinew/viz/rasterizer.h>
#include <sinew/viz/view_hints.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "viz/glb_test_util.h"
#include "viz/two_link_spec.h"

namespace sinew::viz {
namespace {

namespace fs = std::filesystem;

const std::string kBallModel = testing::kDataDir +
                               "/opensim-org/opensim-core/OpenSim/Simulation/Test/"
                               "BouncingBall_HuntCrossley.osim";

std::string ReadText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The Hunt-Crossley bouncing ball with its floor (a ContactHalfSpace on ground, the solid
// y < 0 of ground turned by orientation 0 0 -pi/2) raised to y = `height`.
model::ModelSpec BallWithFloorAt(double height, const fs::path& dir) {
  std::string text = ReadText(kBallModel);
  const std::string floor = "<ContactHalfSpace name=\"floor\">";
  const size_t at = text.find("<location>", text.find(floor));
  const size_t end = text.find("</location>", at);
  text.replace(at, end - at, "<location> 0 " + std::to_string(height) + " 0 ");
  const fs::path file = dir / "ball_raised_floor.osim";
  std::ofstream(file) << text;
  return io::ReadOsim(file.string());
}

class ViewHintsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("sinew_view_hints_" + std::to_string(getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

// The ball translated by `dx` along x over `n` frames of 0.1 s (its free joint's tx).
BodyMotion BallMoving(const model::ModelSpec& ball, double dx, int n) {
  io::Storage table;
  table.labels = {"ball_tx", "ball_ty"};
  for (int k = 0; k < n; ++k) {
    table.time.push_back(0.1 * k);
    table.values.insert(table.values.end(), {dx * k / (n - 1), 0.6});
  }
  return MotionFromTable(ball, table, nullptr);
}

TEST_F(ViewHintsTest, FloorIsTheModelsHalfSpaceOnGroundInTheGlbAndThePage) {
  const model::ModelSpec ball = BallWithFloorAt(0.25, dir_);
  const FloorPlane floor = ModelFloor(ball);
  EXPECT_NEAR(floor.point.y(), 0.25, 1e-12);
  // -x of the frame turned by -1.57079633 (the file's 9 digits of pi/2).
  EXPECT_NEAR((floor.normal - Vec3::UnitY()).norm(), 0.0, 1e-8);
  EXPECT_EQ(floor.source, "ContactHalfSpace floor");

  ExportOptions options;
  options.visual.mode = VisType::kPrimitives;
  const BodyMotion motion = BallMoving(ball, 0.0, 3);
  ExportAnimation(ball, motion, (dir_ / "ball.glb").string(), options);
  ExportAnimation(ball, motion, (dir_ / "ball.html").string(), options);
  // The page embeds the same .glb as base64 in <script id="model">.
  const std::string page = ReadText((dir_ / "ball.html").string());
  const std::string open = "<script id=\"model\" type=\"application/octet-stream\">";
  const size_t begin = page.find(open) + open.size();
  const auto embedded = io::DecodeBase64(page.substr(begin, page.find("</script>", begin) - begin));
  ASSERT_TRUE(embedded.has_value());
  const std::vector<uint8_t> file = ReadFileBytes((dir_ / "ball.glb").string());
  EXPECT_EQ(*embedded, file);
  const nlohmann::json extras = testing::ParseGlb(file).doc["scenes"][0]["extras"];
  EXPECT_NEAR(extras["floor"]["point"][1].get<double>(), 0.25, 1e-12);
  EXPECT_NEAR(extras["floor"]["normal"][1].get<double>(), 1.0, 1e-8);
  EXPECT_EQ(extras["floor"]["source"], "ContactHalfSpace floor");
  EXPECT_NEAR(extras["grid"]["center"][1].get<double>(), 0.25, 1e-7);  // the grid lies on it
  EXPECT_EQ(extras["follow_body"], -1);                                // the ball does not move
  EXPECT_FALSE(extras.contains("contact_arrows"));
  // The floor's slab is marked as the stand-in of an unbounded shape (the viewer, like
  // render, frames the model without it); the ball is not.
  int unbounded = 0, bounded = 0;
  const nlohmann::json doc = testing::ParseGlb(file).doc;
  for (const nlohmann::json& node : doc["nodes"]) {
    if (!node.contains("extras") || !node["extras"].contains("source")) continue;
    const bool marked = node["extras"].value("unbounded", false);
    if (node["extras"]["source"] == "ContactHalfSpace") {
      EXPECT_TRUE(marked);
      ++unbounded;
    } else if (node["extras"]["source"] == "ContactSphere") {
      EXPECT_FALSE(marked);
      ++bounded;
    }
  }
  EXPECT_EQ(unbounded, 1);
  EXPECT_EQ(bounded, 1);
  // An explicit floor (simulate's --ground-plane) wins.
  options.floor = HorizontalFloor(-0.5, "--ground-plane");
  ExportAnimation(ball, motion, (dir_ / "ball.glb").string(), options);
  const nlohmann::json plane =
      testing::ParseGlb(ReadFileBytes((dir_ / "ball.glb").string())).doc["scenes"][0]["extras"];
  EXPECT_EQ(plane["floor"]["point"][1], -0.5);
  EXPECT_EQ(plane["floor"]["source"], "--ground-plane");
}

TEST_F(ViewHintsTest, WithoutAHalfSpaceTheFloorIsYZeroUnlessTheModelHangsBelowIt) {
  const model::ModelSpec two_link = testing::TwoLinkSpec();
  VisualOptions primitives;
  primitives.mode = VisType::kPrimitives;
  const VisualScene scene = BuildVisualScene(two_link, primitives);
  EXPECT_EQ(ModelFloor(two_link).source, "y = 0");
  EXPECT_EQ(ModelFloor(two_link).point, Vec3::Zero());
  // A model hanging from ground's origin (a pendulum, 1 m long): y = 0 cuts through it.
  const FloorPlane hanging =
      FloorUnder(ModelFloor(two_link), {Vec3(-0.1, -1, -0.1), Vec3(0.1, 0, 0.1)});
  EXPECT_EQ(hanging.source, "lowest point");
  EXPECT_EQ(hanging.point.y(), -1.0);
  // The model's floor in a picture of the still two-link model: its bodies start at y = 0.
  const BodyMotion still = testing::SwingMotion(1, 0.0, 0.1, 0.0);
  EXPECT_EQ(ViewFloor(two_link, scene, still).source,
            FloorUnder(ModelFloor(two_link), FirstPoseBounds(scene, still)).source);
  // A model standing on y = 0 keeps it.
  const FloorPlane standing = FloorUnder(ModelFloor(two_link), {Vec3(0, -0.01, 0), Vec3(1, 2, 1)});
  EXPECT_EQ(standing.source, "y = 0");
}

TEST_F(ViewHintsTest, CameraFollowsABodyThatMovesFarAndTheGridCoversItsPath) {
  const model::ModelSpec ball = io::ReadOsim(kBallModel);
  VisualOptions primitives;
  primitives.mode = VisType::kPrimitives;
  const VisualScene scene = BuildVisualScene(ball, primitives);
  // The ball (diameter 1 m: the model's size is its box's diagonal, 1.73 m) rolled 10 m.
  const BodyMotion rolled = BallMoving(ball, 10.0, 11);
  const ViewHints far = MakeViewHints(ball, scene, rolled, ModelFloor(ball));
  EXPECT_EQ(far.follow_body, 1);
  // The footprint runs from the ball's side at x = -0.5 to its centre at x = 10; half the
  // model's size to spare on each side.
  // (The file's floor normal is 3e-9 off vertical.)
  EXPECT_NEAR(far.grid_center.x(), 4.75, 1e-7);
  EXPECT_NEAR(far.grid_center.y(), 0.0, 1e-7);
  EXPECT_NEAR(far.grid_size, 10.5 + std::sqrt(3.0), 1e-7);
  // Moved 1 m, less than its size: no follow; the grid at least twice the model's size.
  const ViewHints near = MakeViewHints(ball, scene, BallMoving(ball, 1.0, 11), ModelFloor(ball));
  EXPECT_EQ(near.follow_body, model::kNone);
  EXPECT_NEAR(near.grid_size, 2 * std::sqrt(3.0), 1e-7);
  // In the .glb: the follow target and the arrows' absence.
  ExportOptions options;
  options.visual = primitives;
  ExportAnimation(ball, rolled, (dir_ / "rolled.glb").string(), options);
  const nlohmann::json doc = testing::ParseGlb(ReadFileBytes((dir_ / "rolled.glb").string())).doc;
  EXPECT_EQ(doc["scenes"][0]["extras"]["follow_body"], 1);
  EXPECT_NEAR(doc["scenes"][0]["extras"]["grid"]["size"].get<double>(), far.grid_size, 1e-12);
}

TEST_F(ViewHintsTest, RendererFloorLiesOnTheGivenPlane) {
  // The sphere of radius 0.3 at the origin: a floor on its lowest point is the default; a floor
  // given there draws the same picture, one 2 m lower another.
  VisualScene scene;
  scene.bodies.push_back({"ground", 0, {}});
  VisualPart part;
  part.mesh = UnitSphere();
  part.scale = Vec3::Constant(0.3);
  scene.bodies.push_back({"ball", 1, {part}});
  const std::vector<Transform> X_GB(2);
  RenderOptions options;
  options.width = options.height = 100;
  options.floor = true;
  const Image lowest = RenderFramed(scene, X_GB, options);
  options.floor_plane = HorizontalFloor(-0.3, "test");
  EXPECT_EQ(RenderFramed(scene, X_GB, options).rgb, lowest.rgb);
  options.floor_plane = HorizontalFloor(-2.3, "test");
  EXPECT_NE(RenderFramed(scene, X_GB, options).rgb, lowest.rgb);
}

}  // namespace
}  // namespace sinew::viz

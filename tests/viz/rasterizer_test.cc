// The software renderer against hand-computed projections.
#include <gtest/gtest.h>
#include <sinew/viz/primitive_shapes.h>
#include <sinew/viz/rasterizer.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace sinew::viz {
namespace {

VisualScene OnePart(std::shared_ptr<const io::TriangleMesh> mesh, const Vec3& scale,
                    const Vec3& color, const Transform& X_BG = Transform()) {
  VisualScene scene;
  VisualBody body;
  body.body = 0;
  VisualPart part;
  part.mesh = std::move(mesh);
  part.scale = scale;
  part.color = color;
  part.X_BG = X_BG;
  body.parts.push_back(part);
  scene.bodies.push_back(body);
  return scene;
}

int CountNotBackground(const Image& image) {
  int n = 0;
  for (size_t i = 0; i < image.rgb.size(); i += 3) {
    if (image.rgb[i] != 245 || image.rgb[i + 1] != 245 || image.rgb[i + 2] != 245) ++n;
  }
  return n;
}

TEST(RasterizerTest, BoxProjectsToTheHandComputedSquare) {
  // A cube of half-size 0.5 seen face-on from 3 m: its front face (z = 0.5) projects to a
  // square of half-width f * 0.5 / 2.5 pixels, f = (H / 2) / tan(fov / 2).
  VisualScene scene = OnePart(UnitBox(), Vec3::Constant(0.5), Vec3(1, 0, 0));
  Camera camera;
  camera.eye = Vec3(0, 0, 3);
  camera.fov_y = 0.5;
  RenderOptions options;
  options.width = options.height = 200;
  Image image = RenderScene(scene, {Transform()}, camera, options);
  const double f = 100 / std::tan(0.25);
  const double half = f * 0.5 / 2.5;
  const double expected = 4 * half * half;
  // Edge pixels are blended: allow one pixel around the perimeter.
  EXPECT_NEAR(CountNotBackground(image), expected, 8 * half + 4);
  // The centre is red (lit), the corner is background.
  const uint8_t* centre = image.At(100, 100);
  EXPECT_GT(centre[0], 150);
  EXPECT_LT(centre[1], 10);
  EXPECT_EQ(image.At(0, 0)[0], 245);
}

TEST(RasterizerTest, NearerSurfaceHidesFartherOneAndBodiesFollowTheirPoses) {
  // A green sphere at z = 1 in front of a red box at the origin, seen from +z.
  VisualScene scene = OnePart(UnitBox(), Vec3::Constant(0.5), Vec3(1, 0, 0));
  VisualBody ball;
  ball.body = 1;
  VisualPart part;
  part.mesh = UnitSphere();
  part.scale = Vec3::Constant(0.2);
  part.color = Vec3(0, 1, 0);
  ball.parts.push_back(part);
  scene.bodies.push_back(ball);
  Camera camera;
  camera.eye = Vec3(0, 0, 4);
  RenderOptions options;
  options.width = options.height = 100;
  Image image =
      RenderScene(scene, {Transform(), Transform::Translation(Vec3(0, 0, 1))}, camera, options);
  EXPECT_GT(image.At(50, 50)[1], 100);  // green in front
  EXPECT_LT(image.At(50, 50)[0], 10);
  // Move the sphere behind the box: the centre turns red.
  image =
      RenderScene(scene, {Transform(), Transform::Translation(Vec3(0, 0, -1))}, camera, options);
  EXPECT_GT(image.At(50, 50)[0], 100);
  EXPECT_LT(image.At(50, 50)[1], 10);
}

TEST(RasterizerTest, OverlayIsDrawnOverTheModelAndLeavesTheRestAlone) {
  // A green sphere behind a red box (seen from +z), given as an overlay part in ground: it
  // shows at the centre as the viewer's contact arrows do (over the model), and only the
  // pixels it covers change.
  VisualScene scene = OnePart(UnitBox(), Vec3::Constant(0.5), Vec3(1, 0, 0));
  Camera camera;
  camera.eye = Vec3(0, 0, 4);
  RenderOptions options;
  options.width = options.height = 100;
  const Image plain = RenderScene(scene, {Transform()}, camera, options);
  VisualPart ball;
  ball.mesh = UnitSphere();
  ball.scale = Vec3::Constant(0.2);
  ball.color = Vec3(0, 1, 0);
  ball.X_BG = Transform::Translation(Vec3(0, 0, -1));
  options.overlay = {ball};
  const Image over = RenderScene(scene, {Transform()}, camera, options);
  EXPECT_GT(over.At(50, 50)[1], 100);  // green over the box
  EXPECT_LT(over.At(50, 50)[0], 10);
  // The sphere (radius 0.2 at 5 m) spans f 0.2 / 5 = 6.5 pixels either side of the centre, f =
  // 50 / tan(0.3): the corners, farther than 10 pixels, are the plain picture's.
  for (int y = 0; y < 100; ++y) {
    for (int x = 0; x < 100; ++x) {
      if (std::hypot(x + 0.5 - 50, y + 0.5 - 50) < 10) continue;
      EXPECT_TRUE(std::equal(over.At(x, y), over.At(x, y) + 3, plain.At(x, y))) << x << ", " << y;
    }
  }
}

TEST(RasterizerTest, FramedCameraKeepsTheSceneInsideTheImage) {
  VisualScene scene = OnePart(UnitSphere(), Vec3(0.1, 0.9, 0.1), Vec3(0.5, 0.5, 0.5),
                              Transform::Translation(Vec3(2, 0, 0)));
  const auto bounds = SceneBounds(scene, {Transform()});
  EXPECT_NEAR(bounds.first.y(), -0.9, 1e-6);
  EXPECT_NEAR(bounds.second.x(), 2.1, 1e-6);
  RenderOptions options;
  options.width = 160;
  options.height = 120;
  Image image = RenderScene(scene, {Transform()},
                            FrameCamera(bounds, ParseViewDirection("front"), 160.0 / 120), options);
  EXPECT_GT(CountNotBackground(image), 200);
  for (int x = 0; x < image.width; ++x) {  // nothing touches the top or bottom rows
    EXPECT_EQ(image.At(x, 0)[0], 245);
    EXPECT_EQ(image.At(x, image.height - 1)[0], 245);
  }
  EXPECT_THROW(ParseViewDirection("sideways"), Error);
}

TEST(RasterizerTest, FloorAndShadowAppearWhenAsked) {
  // A sphere on a floor at its lowest point: floor samples are background * 0.9 and shadow
  // samples floor * 0.7, both unlit (RGB 0.864 and 0.605 of full scale).
  VisualScene scene = OnePart(UnitSphere(), Vec3::Constant(0.3), Vec3(1, 0, 0));
  RenderOptions options;
  options.width = options.height = 120;
  options.floor = true;
  const auto bounds = SceneBounds(scene, {Transform()});
  const Camera camera = FrameCamera(bounds, Vec3(1, 0.8, 0.3), 1.0);
  Image image = RenderScene(scene, {Transform()}, camera, options);
  int floor = 0, shadow = 0;
  for (size_t i = 0; i < image.rgb.size(); i += 3) {
    const uint8_t* p = &image.rgb[i];
    if (p[0] == p[1] && p[1] == p[2]) {
      floor += std::abs(p[0] - 220) <= 1;   // 0.96 * 0.9 * 255
      shadow += std::abs(p[0] - 154) <= 1;  // 0.96 * 0.9 * 0.7 * 255
    }
  }
  EXPECT_GT(floor, 1000);
  EXPECT_GT(shadow, 100);
  options.floor = false;
  image = RenderScene(scene, {Transform()}, camera, options);
  EXPECT_EQ(image.At(0, image.height - 1)[0], 245);  // no floor in the corner
}

TEST(RasterizerTest, MemoryIsCappedNotOnlyPixels) {
  // 4 samples of a float depth and a Vec3 colour, and 3 bytes of the final image, per pixel.
  EXPECT_EQ(RenderBytes(800, 600), 800u * 600u * (4u * (4u + 24u) + 3u));
  EXPECT_NO_THROW(CheckRenderSize(3840, 2160));  // 4K: about 950 MB
  EXPECT_LE(RenderBytes(3840, 2160), kMaxRenderBytes);
  try {
    CheckRenderSize(8192, 8192);  // allowed by the pixel limits; 7.4 GB of buffers
    FAIL() << "8192 x 8192 must be refused";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              "render: a 8192 x 8192 image needs 7360 MiB of frame buffers (2x2 supersampled), "
              "more than the cap of 1024 MiB; ask for fewer pixels (about 9 million at most)");
  }
  EXPECT_THROW(CheckRenderSize(0, 10), Error);
  EXPECT_THROW(CheckRenderSize(20000, 1), Error);
}

}  // namespace
}  // namespace sinew::viz

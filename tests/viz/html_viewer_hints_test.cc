// The HTML viewer's use of the exporter's hints in headless Chromium: a ball rolling 10 m is
// followed by the camera, its contact force is drawn as a green arrow that the forces checkbox
// (or #forces=0) hides, and the legend states the arrows' scale and the grid's floor; a
// bouncing ball is followed by its position averaged over the smoothing window.
#include <gtest/gtest.h>
#include <sinew/io/osim_reader.h>
#include <sinew/io/storage.h>
#include <sinew/math/types.h>
#include <sinew/viz/export_animation.h>
#include <sinew/viz/image.h>
#include <sinew/viz/motion_poses.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>

#include "viz/chromium_util.h"
#include "viz/two_link_spec.h"

namespace sinew::viz {
namespace {

namespace fs = std::filesystem;

// Pixels in the arrows' green.
int GreenPixels(const Image& image) { return testing::PixelsOfColour(image, 1, 100, 50); }

// The value of attribute `name` of the page's <body>.
std::string BodyAttribute(const std::string& dom, const std::string& name) {
  const size_t body = dom.find("<body");
  const size_t at = dom.find(name + "=\"", body);
  if (body == std::string::npos || at == std::string::npos || at > dom.find('>', body)) return "?";
  const size_t begin = at + name.size() + 2;
  return dom.substr(begin, dom.find('"', begin) - begin);
}

// Each test: headless Chromium (skipped without it), a scratch folder, the bouncing-ball model.
class HtmlViewerHintsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    chromium = testing::FindChromium();
    if (chromium.empty()) {
      GTEST_SKIP() << "chromium is not installed (scripts/setup.sh installs it); viewer not tested";
    }
    dir = fs::temp_directory_path() /
          ("sinew_viewer_" +
           std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
           std::to_string(getpid()));
    fs::create_directories(dir);
    ball = io::ReadOsim(
        testing::kDataDir +
        "/opensim-org/opensim-core/OpenSim/Simulation/Test/BouncingBall_HuntCrossley.osim");
  }
  std::string chromium;
  fs::path dir;
  model::ModelSpec ball;
};

TEST_F(HtmlViewerHintsTest, FollowsTheRollingBallAndDrawsItsContactForce) {
  // The ball (radius 0.5 m) rolls 10 m along x on its floor in 2 s, the floor pushing up
  // with its weight.
  io::Storage coordinates, contacts;
  coordinates.labels = {"ball_tx", "ball_ty"};
  contacts.labels = {"contact.ball.force.X",  "contact.ball.force.Y",  "contact.ball.force.Z",
                     "contact.ball.torque.X", "contact.ball.torque.Y", "contact.ball.torque.Z"};
  for (int k = 0; k <= 20; ++k) {
    coordinates.time.push_back(0.1 * k);
    coordinates.values.insert(coordinates.values.end(), {0.5 * k, 0.5});
    contacts.time.push_back(0.1 * k);
    contacts.values.insert(contacts.values.end(), {0, 9.8065, 0, 0, 0, 0});
  }
  ExportOptions options;
  options.visual.mode = VisType::kPrimitives;
  options.contacts = &contacts;
  ExportAnimation(ball, MotionFromTable(ball, coordinates, nullptr), (dir / "ball.html").string(),
                  options);
  const std::string url = "file://" + (dir / "ball.html").string();

  const std::string dom = testing::DumpDom(chromium, url + "#t=1.5&pause", dir / "dom.html", 2500);
  EXPECT_EQ(BodyAttribute(dom, "data-ready"), "1") << dom.substr(0, 2000);
  EXPECT_EQ(BodyAttribute(dom, "data-follow"), "ball");  // it moves 10 m, 5.8 times its size
  EXPECT_EQ(BodyAttribute(dom, "data-forces"), "1");
  EXPECT_NE(dom.find("body weight (9.8 N) = 0.500 m"), std::string::npos);
  EXPECT_NE(dom.find("on the floor (ContactHalfSpace floor)"), std::string::npos);
  const std::string unfollowed =
      testing::DumpDom(chromium, url + "#t=1.5&pause&follow=&forces=0", dir / "off.html", 2500);
  EXPECT_EQ(BodyAttribute(unfollowed, "data-follow"), "");
  EXPECT_EQ(BodyAttribute(unfollowed, "data-forces"), "0");

  // Followed, the ball is in view at 1.5 s (7.5 m from where it started) with its arrow; the
  // checkbox's state hides the arrow.
  const Image with = testing::Screenshot(chromium, url + "#t=1.5&pause", dir / "with.png", 2500);
  const Image without =
      testing::Screenshot(chromium, url + "#t=1.5&pause&forces=0", dir / "without.png", 2500);
  EXPECT_GT(GreenPixels(with), 100) << "no arrow: see " << dir;
  EXPECT_LT(GreenPixels(without), 10) << "see " << dir;  // a stray blended pixel or so
  if (!HasFailure()) fs::remove_all(dir);
}

// The camera target the page reports (`data-target`: x y z).
Vec3 Target(const std::string& dom) {
  std::istringstream in(BodyAttribute(dom, "data-target"));
  Vec3 p = Vec3::Constant(NAN);
  in >> p.x() >> p.y() >> p.z();
  return p;
}

// The ball rolls along x at 5 m/s while bouncing, y = 0.5 + 0.3 |sin(4 pi t)| (a bounce every
// 0.25 s), tabled every 10 ms over 2 s. Followed with the default window (0.5 s, two bounces),
// the camera's target is the mean position over the window: x exactly the ball's (a straight
// line's centred mean: no lag), y the mean height, 0.5 + 0.3 (2 / pi) for the continuous
// window; the viewer's mean is over the 51 samples of the window's 50 intervals, whose two end
// samples lie at bounces (|sin| = 0) here, so it is 50/51 of the trapezoid rule's mean (itself
// within 3e-4 m of the integral): 0.6873 m, against 0.6910 m continuous, hence 5e-3 m. With
// #smooth=0 the target is the ball itself, at the bottom of a bounce (t = 1.5 s) and near the
// top (1.62 s, a row of the table: the top itself, 1.625 s, lies between rows).
TEST_F(HtmlViewerHintsTest, FollowsABouncingBallByItsMeanPosition) {
  io::Storage coordinates;
  coordinates.labels = {"ball_tx", "ball_ty"};
  for (int k = 0; k <= 200; ++k) {
    const double t = 0.01 * k;
    coordinates.time.push_back(t);
    coordinates.values.insert(coordinates.values.end(),
                              {5.0 * t, 0.5 + 0.3 * std::abs(std::sin(4.0 * M_PI * t))});
  }
  ExportOptions options;
  options.visual.mode = VisType::kPrimitives;
  ExportAnimation(ball, MotionFromTable(ball, coordinates, nullptr), (dir / "bounce.html").string(),
                  options);
  const std::string url = "file://" + (dir / "bounce.html").string();

  const std::string smoothed =
      testing::DumpDom(chromium, url + "#t=1.5&pause", dir / "smoothed.html", 2500);
  ASSERT_EQ(BodyAttribute(smoothed, "data-follow"), "ball") << smoothed.substr(0, 2000);
  const Vec3 mean = Target(smoothed);
  EXPECT_NEAR(mean.x(), 7.5, 1e-6);
  EXPECT_NEAR(mean.y(), 0.5 + 0.3 * 2.0 / M_PI, 5e-3);
  EXPECT_NEAR(mean.z(), 0.0, 1e-6);

  const Vec3 bottom =
      Target(testing::DumpDom(chromium, url + "#t=1.5&pause&smooth=0", dir / "bottom.html", 2500));
  EXPECT_NEAR(bottom.x(), 7.5, 1e-6);
  EXPECT_NEAR(bottom.y(), 0.5, 1e-6);
  const Vec3 top =
      Target(testing::DumpDom(chromium, url + "#t=1.62&pause&smooth=0", dir / "top.html", 2500));
  EXPECT_NEAR(top.x(), 8.1, 1e-6);
  EXPECT_NEAR(top.y(), 0.5 + 0.3 * std::abs(std::sin(4.0 * M_PI * 1.62)), 1e-6);
  if (!HasFailure()) fs::remove_all(dir);
}

}  // namespace
}  // namespace sinew::viz

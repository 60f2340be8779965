// The HTML viewer's use of the exporter's hints in headless Chromium: a ball rolling 10 m is
// followed by the camera, its contact force is drawn as a green arrow that the forces checkbox
// (or #forces=0) hides, and the legend states the arrows' scale and the grid's floor.
#include <gtest/gtest.h>
#include <sinew/io/osim_reader.h>
#include <sinew/io/storage.h>
#include <sinew/viz/export_animation.h>
#include <sinew/viz/image.h>
#include <sinew/viz/motion_poses.h>
#include <unistd.h>

#include <filesystem>
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

TEST(HtmlViewerHintsTest, FollowsTheRollingBallAndDrawsItsContactForce) {
  const std::string chromium = testing::FindChromium();
  if (chromium.empty()) {
    GTEST_SKIP() << "chromium is not installed (scripts/setup.sh installs it); viewer not tested";
  }
  const fs::path dir =
      fs::temp_directory_path() / ("sinew_viewer_hints_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const model::ModelSpec ball = io::ReadOsim(
      testing::kDataDir +
      "/opensim-org/opensim-core/OpenSim/Simulation/Test/BouncingBall_HuntCrossley.osim");
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

}  // namespace
}  // namespace sinew::viz

// The HTML viewer in headless Chromium (software WebGL through SwiftShader): the page must show
// the model (not a blank canvas) and the picture must change as the animation plays.
#include <gtest/gtest.h>
#include <sinew/io/osim_reader.h>
#include <sinew/io/storage.h>
#include <sinew/viz/export_animation.h>
#include <sinew/viz/html_viewer.h>
#include <sinew/viz/image.h>
#include <sinew/viz/motion_poses.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "viz/chromium_util.h"
#include "viz/two_link_spec.h"

namespace sinew::viz {
namespace {

namespace fs = std::filesystem;

using testing::FindChromium;
using testing::Screenshot;

// Pixels of the 3D view (between the title and the control bar) unlike the background.
double ForegroundFraction(const Image& image) {
  int count = 0, total = 0;
  for (int y = 40; y < image.height - 50; ++y) {
    for (int x = 0; x < image.width; ++x, ++total) {
      const uint8_t* p = image.At(x, y);
      const int d = std::abs(p[0] - 0x20) + std::abs(p[1] - 0x24) + std::abs(p[2] - 0x2a);
      if (d > 60) ++count;
    }
  }
  return static_cast<double>(count) / total;
}

double DifferentFraction(const Image& a, const Image& b) {
  int count = 0;
  for (int y = 40; y < a.height - 50; ++y) {
    for (int x = 0; x < a.width; ++x) {
      const uint8_t *p = a.At(x, y), *q = b.At(x, y);
      if (std::abs(p[0] - q[0]) + std::abs(p[1] - q[1]) + std::abs(p[2] - q[2]) > 60) ++count;
    }
  }
  return static_cast<double>(count) / (a.width * (a.height - 90));
}

TEST(HtmlViewerTest, ShowsTheModelAndAnimatesInHeadlessChromium) {
  const std::string chromium = FindChromium();
  if (chromium.empty()) {
    GTEST_SKIP() << "chromium is not installed (scripts/setup.sh installs it); viewer not tested";
  }
  const fs::path dir =
      fs::temp_directory_path() / ("sinew_viewer_test_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const fs::path page = dir / "two_link.html";
  ExportOptions options;
  options.visual.mode = VisType::kPrimitives;
  // 2 s of a pendulum swinging through 1.2 rad.
  ExportAnimation(testing::TwoLinkSpec(), testing::SwingMotion(21, 0.0, 0.1, 0.06), page.string(),
                  options);
  const std::string url = "file://" + page.string();
  // The page paused at 0 s and at 1.5 s (the time slider's path: AnimationMixer.setTime).
  // Playing is not compared: how much virtual time is left after loading varies with the
  // machine's load, so a screenshot of the playing page is not reproducible.
  const Image start = Screenshot(chromium, url + "#t=0&pause", dir / "start.png", 2500);
  const Image later = Screenshot(chromium, url + "#t=1.5&pause", dir / "later.png", 2500);
  ASSERT_EQ(start.width, later.width);
  // The skeleton covers a few percent of the view (spheres and links), not nothing.
  EXPECT_GT(ForegroundFraction(start), 0.01) << "blank scene: see " << dir;
  EXPECT_GT(ForegroundFraction(later), 0.01) << "blank scene: see " << dir;
  // The link has swung by about 0.9 rad: many pixels changed.
  EXPECT_GT(DifferentFraction(start, later), 0.005) << "no motion: see " << dir;
  if (!HasFailure()) fs::remove_all(dir);
}

// Pixels of the 3D view in muscle red.
int RedPixels(const Image& image) { return testing::PixelsOfColour(image, 0, 120, 60); }

TEST(HtmlViewerTest, ShowsArm26MusclesMovingAsRedLines) {
  const std::string chromium = FindChromium();
  if (chromium.empty()) {
    GTEST_SKIP() << "chromium is not installed (scripts/setup.sh installs it); viewer not tested";
  }
  const fs::path dir =
      fs::temp_directory_path() / ("sinew_viewer_paths_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const model::ModelSpec arm26 =
      io::ReadOsim(testing::kDataDir + "/opensim-org/opensim-models/Models/Arm26/arm26.osim");
  io::Storage elbow;  // the elbow flexes from straight to 2.2 rad in 1 s
  elbow.labels = {"r_elbow_flex"};
  elbow.time = {0.0, 0.25, 0.5, 0.75, 1.0};
  elbow.values = {0.0, 0.55, 1.1, 1.65, 2.2};
  ExportOptions options;
  options.visual.mode = VisType::kNone;  // the muscles alone
  const BodyMotion motion = MotionFromTable(arm26, elbow, nullptr);
  ExportAnimation(arm26, motion, (dir / "paths.html").string(), options);
  options.paths = false;
  ExportAnimation(arm26, motion, (dir / "none.html").string(), options);
  const std::string url = "file://" + (dir / "paths.html").string();
  const Image straight = Screenshot(chromium, url + "#t=0&pause", dir / "straight.png", 2500);
  const Image flexed = Screenshot(chromium, url + "#t=0.9&pause", dir / "flexed.png", 2500);
  const Image none = Screenshot(chromium, "file://" + (dir / "none.html").string() + "#t=0&pause",
                                dir / "none.png", 2500);
  EXPECT_GT(RedPixels(straight), 100) << "no muscle lines: see " << dir;
  EXPECT_GT(RedPixels(flexed), 100) << "no muscle lines: see " << dir;
  EXPECT_EQ(RedPixels(none), 0) << "see " << dir;
  // At 0.9 s (frame 0.75 s: 1.65 rad) the forearm's muscles have followed the elbow.
  EXPECT_GT(DifferentFraction(straight, flexed), 0.002) << "the lines did not move: see " << dir;
  if (!HasFailure()) fs::remove_all(dir);
}

TEST(HtmlViewerTest, PageIsSelfContained) {
  const std::string page = MakeViewerHtml({1, 2, 3}, "a <model>");
  EXPECT_NE(page.find("<title>a &lt;model&gt;</title>"), std::string::npos);
  EXPECT_NE(page.find("\"three\":\"data:text/javascript;base64,"), std::string::npos);
  EXPECT_EQ(page.find("@SINEW_"), std::string::npos);  // every placeholder filled
  // No network: nothing is loaded from http(s) URLs in src/href attributes or imports.
  EXPECT_EQ(page.find("src=\"http"), std::string::npos);
  EXPECT_EQ(page.find("from 'http"), std::string::npos);
}

}  // namespace
}  // namespace sinew::viz

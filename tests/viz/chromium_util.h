// Test helpers: the HTML viewer in headless Chromium (software WebGL through SwiftShader), as a
// screenshot or as the page's DOM after its scripts ran.
#pragma once

#include <gtest/gtest.h>
#include <sinew/viz/image.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace sinew::viz::testing {

/// The first Chromium found in PATH, or "".
inline std::string FindChromium() {
  for (const char* name : {"chromium", "chromium-browser", "google-chrome", "chrome"}) {
    if (std::system(("command -v " + std::string(name) + " >/dev/null 2>&1").c_str()) == 0) {
      return name;
    }
  }
  return "";
}

/// Runs headless Chromium on `url` with `what` ("--screenshot=FILE" or "--dump-dom") after
/// `budget_ms` of virtual time (timers and animation frames run that long without waiting),
/// stdout to `out`, a fresh profile beside it.
inline void RunChromium(const std::string& chromium, const std::string& url,
                        const std::filesystem::path& out, const std::string& what, int budget_ms) {
  const std::filesystem::path profile = out.parent_path() / ("profile_" + out.stem().string());
  const std::string command = chromium +
                              " --headless=new --no-sandbox --disable-gpu --use-angle=swiftshader"
                              " --enable-unsafe-swiftshader --hide-scrollbars --no-first-run"
                              " --user-data-dir=" +
                              profile.string() + " --window-size=480,360 --virtual-time-budget=" +
                              std::to_string(budget_ms) + " " + what + " '" + url + "' >" +
                              out.string() + " 2>" + out.string() + ".log";
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
}

/// Screenshot of `url` (480 x 360).
inline Image Screenshot(const std::string& chromium, const std::string& url,
                        const std::filesystem::path& png, int budget_ms) {
  RunChromium(chromium, url, png.string() + ".out", "--screenshot=" + png.string(), budget_ms);
  return DecodePng(ReadFileBytes(png.string()), png.string());
}

/// The page's DOM (HTML text) after its scripts ran.
inline std::string DumpDom(const std::string& chromium, const std::string& url,
                           const std::filesystem::path& html, int budget_ms) {
  RunChromium(chromium, url, html, "--dump-dom", budget_ms);
  std::ifstream in(html);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Pixels of the 3D view (between the title and the control bar) whose channel `c` (0 red,
/// 1 green, 2 blue) is above `least` and above the other two by more than `margin`.
inline int PixelsOfColour(const Image& image, int c, int least, int margin) {
  int count = 0;
  for (int y = 40; y < image.height - 50; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const uint8_t* p = image.At(x, y);
      const int a = p[(c + 1) % 3], b = p[(c + 2) % 3];
      if (p[c] > least && p[c] > a + margin && p[c] > b + margin) ++count;
    }
  }
  return count;
}

}  // namespace sinew::viz::testing

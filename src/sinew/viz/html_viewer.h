// The self-contained HTML viewer: one file with three.js, the glTF loader and the model.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace sinew::viz {

/// An HTML page that shows the .glb `glb` with three.js and plays its animation (play/pause,
/// speed, time slider). Everything is inside the page (modules as data: URLs in an import
/// map, the model as base64), so it opens offline from a file. The URL hash `#t=T&pause`
/// opens it paused at time T (s from the motion's start).
std::string MakeViewerHtml(const std::vector<uint8_t>& glb, const std::string& title);

}  // namespace sinew::viz

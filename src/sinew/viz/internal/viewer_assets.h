// Files embedded into the library at build time (see cmake/SinewViewerAssets.cmake): the
// viewer template web/viewer.html and the three.js modules it imports.
#pragma once

#include <string>
#include <string_view>

namespace sinew::viz {

/// The bytes of an embedded file by name: "viewer.html", "three.module.min.js",
/// "GLTFLoader.js", "BufferGeometryUtils.js", "OrbitControls.js". Throws sinew::Error for
/// another name.
std::string_view ViewerAsset(std::string_view name);

}  // namespace sinew::viz

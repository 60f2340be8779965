#include <sinew/common/error.h>
#include <sinew/io/mesh_base64.h>
#include <sinew/viz/html_viewer.h>
#include <sinew/viz/internal/viewer_assets.h>

#include <nlohmann/json.hpp>

namespace sinew::viz {
namespace {

std::string DataUrl(std::string_view javascript) {
  return "data:text/javascript;base64," +
         io::EncodeBase64(reinterpret_cast<const uint8_t*>(javascript.data()), javascript.size());
}

std::string ReplaceAll(std::string text, std::string_view from, std::string_view to) {
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
  return text;
}

std::string EscapeHtml(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '&':
        out += "&amp;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// Replaces the one occurrence of `key` (throws if the template lacks it).
void Fill(std::string& page, std::string_view key, const std::string& value) {
  const size_t at = page.find(key);
  if (at == std::string::npos) throw Error("viewer template lacks " + std::string(key));
  page.replace(at, key.size(), value);
}

}  // namespace

std::string MakeViewerHtml(const std::vector<uint8_t>& glb, const std::string& title) {
  // Modules imported relatively inside a data: URL cannot resolve; point them at the bare
  // specifiers the import map defines.
  const std::string loader =
      ReplaceAll(std::string(ViewerAsset("GLTFLoader.js")), "'../utils/BufferGeometryUtils.js'",
                 "'three/addons/utils/BufferGeometryUtils.js'");
  nlohmann::json imports = {
      {"three", DataUrl(ViewerAsset("three.module.min.js"))},
      {"three/addons/loaders/GLTFLoader.js", DataUrl(loader)},
      {"three/addons/utils/BufferGeometryUtils.js", DataUrl(ViewerAsset("BufferGeometryUtils.js"))},
      {"three/addons/controls/OrbitControls.js", DataUrl(ViewerAsset("OrbitControls.js"))}};
  std::string page(ViewerAsset("viewer.html"));
  const std::string safe_title = EscapeHtml(title);
  // The title appears twice (<title> and the overlay); fill the model last (it is large).
  for (int i = 0; i < 2; ++i) Fill(page, "@SINEW_TITLE@", safe_title);
  Fill(page, "@SINEW_IMPORTMAP@", nlohmann::json{{"imports", imports}}.dump());
  Fill(page, "@SINEW_GLB_BASE64@", io::EncodeBase64(glb.data(), glb.size()));
  return page;
}

}  // namespace sinew::viz

#include <sinew/viz/export_animation.h>
#include <sinew/viz/gltf_writer.h>
#include <sinew/viz/html_viewer.h>
#include <sinew/viz/path_lines.h>
#include <sinew/viz/view_hints.h>

#include <algorithm>
#include <filesystem>

namespace sinew::viz {

BodyMotion ThinMotion(const BodyMotion& motion, double max_fps) {
  if (max_fps <= 0 || motion.times.size() < 3) return motion;
  const double spacing = 1.0 / max_fps;
  BodyMotion out;
  const size_t n = motion.times.size();
  for (size_t k = 0; k < n; ++k) {
    // Keep the first frame, every frame at least `spacing` after the last kept one (with a
    // small tolerance for rounding in the file's times), and the last frame.
    const bool keep =
        k == 0 || k + 1 == n || motion.times[k] - out.times.back() >= spacing * (1 - 1e-9);
    if (!keep) continue;
    out.times.push_back(motion.times[k]);
    out.X_GB.push_back(motion.X_GB[k]);
    if (k < motion.q.size()) out.q.push_back(motion.q[k]);
  }
  return out;
}

ExportFormat ExportFormatOf(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".html" || ext == ".htm") return ExportFormat::kHtml;
  if (ext == ".glb") return ExportFormat::kGlb;
  throw Error(SourceLocation{path, 0}, "",
              "cannot tell the export format from '" + ext + "' (use .glb or .html)");
}

VisualScene ExportAnimation(const model::ModelSpec& spec, const BodyMotion& motion,
                            const std::string& path, const ExportOptions& options) {
  const bool html = ExportFormatOf(path) == ExportFormat::kHtml;
  if (motion.X_GB.size() != motion.times.size()) {
    throw Error("export: the motion has " + std::to_string(motion.times.size()) + " times but " +
                std::to_string(motion.X_GB.size()) + " frames of poses");
  }
  for (size_t k = 0; k < motion.X_GB.size(); ++k) {
    if (motion.X_GB[k].size() != spec.bodies.size()) {
      throw Error("export: frame " + std::to_string(k) + " has " +
                  std::to_string(motion.X_GB[k].size()) + " body poses, the model has " +
                  std::to_string(spec.bodies.size()) + " bodies");
    }
    if (k > 0 && !(motion.times[k] > motion.times[k - 1])) {
      throw Error("export: motion times must increase (frame " + std::to_string(k) + ")");
    }
  }
  VisualScene scene = BuildVisualScene(spec, options.visual);
  AddCollisionParts(options.collision_parts, scene);
  const std::string title = options.title.empty() ? spec.name : options.title;
  const BodyMotion kept = ThinMotion(motion, options.max_fps);
  PathLines lines;
  if (options.paths) lines = CalcPathLines(spec, kept, &scene.warnings);
  if (options.activations && !lines.names.empty()) {
    ShadeByActivation(*options.activations, kept.times, lines);
  }
  const FloorPlane floor = options.floor.value_or(ViewFloor(spec, scene, kept));
  ViewHints hints = MakeViewHints(spec, scene, kept, floor);
  if (options.contacts) {
    hints.arrows = ContactArrowsFromTable(spec, *options.contacts, kept, scene, floor,
                                          options.contact_groups, &scene.warnings);
  }
  std::vector<uint8_t> glb = WriteGlb(scene, kept, title, &lines, &hints);
  if (html) {
    const std::string page = MakeViewerHtml(glb, title);
    WriteFileBytes(path, std::vector<uint8_t>(page.begin(), page.end()));
  } else {
    WriteFileBytes(path, glb);
  }
  return scene;
}

}  // namespace sinew::viz

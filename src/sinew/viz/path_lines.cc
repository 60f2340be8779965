#include <sinew/paths/path_set.h>
#include <sinew/viz/path_lines.h>

#include <set>
#include <string>

namespace sinew::viz {

std::vector<Vec3> PathPolyline(const std::vector<Vec3>& p_GP, const std::vector<int>& arc_of,
                               const std::vector<std::vector<Vec3>>& arc_G) {
  std::vector<Vec3> line;
  line.reserve(p_GP.size());
  for (size_t i = 0; i < p_GP.size(); ++i) {
    line.push_back(p_GP[i]);
    const int w = arc_of[i];
    if (w < 0 || static_cast<size_t>(w) >= arc_G.size()) continue;
    // The arc's ends are the two tangent points, drawn as the path has them.
    const std::vector<Vec3>& arc = arc_G[static_cast<size_t>(w)];
    for (size_t j = 1; j + 1 < arc.size(); ++j) line.push_back(arc[j]);
  }
  return line;
}

PathLines CalcPathLines(const model::ModelSpec& spec, const BodyMotion& motion,
                        Diagnostics* warnings) {
  PathLines lines;
  if (motion.q.size() != motion.X_GB.size()) return lines;
  auto warn = [&](const std::string& component, const std::string& message) {
    if (!warnings) return;
    Diagnostic d;
    d.component = component;
    d.message = message;
    warnings->push_back(std::move(d));
  };
  std::unique_ptr<paths::PathSet> set;
  try {
    set = std::make_unique<paths::PathSet>(spec);
  } catch (const Error& e) {
    warn("", std::string("paths not drawn: ") + e.what());
    return lines;
  }
  // A FunctionBasedPath has a length but no points: nothing to draw.
  std::vector<const paths::GeometryPath*> drawn;
  std::string undrawn;
  for (const paths::GeometryPath& path : set->paths()) {
    if (path.function_path()) {
      undrawn += (undrawn.empty() ? "" : ", ") + path.component();
      continue;
    }
    drawn.push_back(&path);
    lines.names.push_back(path.component());
  }
  if (!undrawn.empty()) {
    warn("",
         "FunctionBasedPaths have no points (only a length), so they are not drawn: " + undrawn);
  }
  paths::PathState state;
  std::vector<Vec3> p_GP;
  std::vector<int> arc_of;
  std::set<size_t> failed;
  lines.vertices.resize(motion.q.size());
  for (size_t k = 0; k < motion.q.size(); ++k) {
    lines.vertices[k].resize(drawn.size());
    for (size_t i = 0; i < drawn.size(); ++i) {
      const paths::GeometryPath& path = *drawn[i];
      try {
        path.CalcState(motion.q[k], motion.X_GB[k], state, /*with_arc_points=*/true);
      } catch (const Error& e) {
        if (failed.insert(i).second) {
          warn(path.component(), "path not drawn at time " + std::to_string(motion.times[k]) +
                                     " s (and maybe later): " + e.what());
        }
        continue;
      }
      p_GP.clear();
      arc_of.clear();
      for (const paths::PathPointState& point : state.points) {
        p_GP.push_back(point.p_GP);
        arc_of.push_back(point.arc_length_to_next >= 0.0
                             ? paths::PathState::ArcIndex(point.wrap, point.tangent)
                             : model::kNone);
      }
      lines.vertices[k][i] = PathPolyline(p_GP, arc_of, state.arc_G);
    }
  }
  return lines;
}

}  // namespace sinew::viz

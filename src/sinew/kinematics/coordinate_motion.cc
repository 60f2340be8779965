#include <sinew/kinematics/coordinate_motion.h>

#include <algorithm>
#include <numbers>
#include <unordered_map>

namespace sinew::kinematics {
namespace {

bool EndsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

MotionColumnMap MapMotionColumns(const model::ModelSpec& spec,
                                 std::span<const std::string> labels) {
  std::unordered_map<std::string, int> by_name, by_path;
  for (int c = static_cast<int>(spec.coordinates.size()) - 1; c >= 0; --c) {
    by_name[spec.coordinates[c].name] = c;  // the first coordinate wins on duplicate names
    if (!spec.coordinates[c].path.empty()) by_path[spec.coordinates[c].path] = c;
  }
  MotionColumnMap map;
  map.coordinate.assign(labels.size(), model::kNone);
  std::vector<bool> driven(spec.coordinates.size(), false);
  for (size_t i = 0; i < labels.size(); ++i) {
    const std::string& label = labels[i];
    if (label == "time") continue;
    int c = model::kNone;
    if (EndsWith(label, "/speed")) continue;
    if (EndsWith(label, "/value")) {
      const std::string path = label.substr(0, label.size() - 6);
      if (auto it = by_path.find(path); it != by_path.end()) {
        c = it->second;
      } else if (auto slash = path.rfind('/'); slash != std::string::npos) {
        // A path the model does not spell the same way: fall back to the last name.
        if (auto jt = by_name.find(path.substr(slash + 1)); jt != by_name.end()) c = jt->second;
      }
    } else if (auto it = by_name.find(label); it != by_name.end()) {
      c = it->second;
    } else if (auto jt = by_path.find(label); jt != by_path.end()) {
      c = jt->second;
    }
    if (c == model::kNone) {
      map.unknown.push_back(label);
    } else {
      map.coordinate[i] = c;
      driven[c] = true;
    }
  }
  for (size_t c = 0; c < driven.size(); ++c) {
    if (!driven[c]) map.missing.push_back(static_cast<int>(c));
  }
  return map;
}

void ApplyMotionRow(const model::ModelSpec& spec, const MotionColumnMap& map,
                    std::span<const double> row, bool in_degrees, std::span<double> q) {
  const size_t n = std::min(row.size(), map.coordinate.size());
  for (size_t i = 0; i < n; ++i) {
    const int c = map.coordinate[i];
    if (c == model::kNone) continue;
    const bool convert =
        in_degrees && spec.coordinates[c].motion_type == model::MotionType::kRotational;
    q[c] = convert ? row[i] * (std::numbers::pi / 180.0) : row[i];
  }
}

}  // namespace sinew::kinematics

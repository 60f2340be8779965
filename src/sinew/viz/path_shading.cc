#include <sinew/viz/path_lines.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace sinew::viz {

Vec3 PathColor(const PathLines& lines, double activation) {
  if (std::isnan(activation)) return lines.color;
  const double a = std::clamp(activation, 0.0, 1.0);
  return (1 - a) * InactiveColor() + a * lines.color;
}

int ShadeByActivation(const io::Storage& table, const std::vector<double>& times,
                      PathLines& lines) {
  // The activation column of each path (-1: none).
  std::vector<int> column(lines.names.size(), -1);
  int found = 0;
  for (size_t i = 0; i < lines.names.size(); ++i) {
    const std::string& component = lines.names[i];
    const std::string name = component.substr(component.rfind('/') + 1);
    for (int c = 0; c < table.NumColumns() && column[i] < 0; ++c) {
      const std::string& label = table.labels[static_cast<size_t>(c)];
      if (label == component + "/activation" || label == name + ".activation") column[i] = c;
    }
    if (column[i] >= 0) ++found;
  }
  if (found == 0 || table.NumRows() == 0) return 0;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  lines.activation.assign(times.size(), std::vector<double>(lines.names.size(), nan));
  for (size_t k = 0; k < times.size(); ++k) {
    // The rows around times[k] (the first or last row outside the table's range).
    const auto it = std::lower_bound(table.time.begin(), table.time.end(), times[k]);
    const int hi = std::min(static_cast<int>(it - table.time.begin()), table.NumRows() - 1);
    const int lo = std::max(0, hi - 1);
    const double span = table.time[hi] - table.time[lo];
    const double s = span > 0 ? std::clamp((times[k] - table.time[lo]) / span, 0.0, 1.0) : 1.0;
    for (size_t i = 0; i < column.size(); ++i) {
      if (column[i] < 0) continue;
      const double a0 = table.Value(lo, column[i]), a1 = table.Value(hi, column[i]);
      lines.activation[k][i] = std::clamp(a0 + s * (a1 - a0), 0.0, 1.0);
    }
  }
  return found;
}

}  // namespace sinew::viz

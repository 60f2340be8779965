#include "apps/sinew/tables.h"

#include <sinew/common/error.h>
#include <sinew/io/storage_labels.h>

#include <cmath>
#include <iostream>
#include <numbers>
#include <optional>

#include "apps/sinew/notices.h"

namespace sinew::cli {

io::Storage ReadTableFor(const std::string& path, const model::ModelSpec& spec) {
  io::Storage table = io::ReadStorage(path);
  for (const Diagnostic& note : table.notes) std::cerr << "sinew: note: " << note.Format() << "\n";
  if (table.in_degrees_stated || table.in_degrees) return table;
  std::vector<std::string> rotational;
  for (const model::CoordinateSpec& c : spec.coordinates) {
    if (c.motion_type == model::MotionType::kRotational) rotational.push_back(c.name);
  }
  std::vector<std::string> suspicious;
  for (int column = 0; column < table.NumColumns(); ++column) {
    const std::optional<io::CoordinateColumn> parsed =
        io::ParseColumnLabel(table.labels[column], rotational);
    if (!parsed || parsed->kind != io::CoordinateColumnKind::kValue) continue;
    for (int row = 0; row < table.NumRows(); ++row) {
      if (std::abs(table.Value(row, column)) > 2 * std::numbers::pi) {
        suspicious.push_back(table.labels[column]);
        break;
      }
    }
  }
  if (!suspicious.empty()) {
    std::cerr << "sinew: warning: " << path
              << " has no inDegrees line, so its angles are read as radians (as OpenSim reads"
                 " it), but "
              << suspicious.size()
              << (suspicious.size() == 1 ? " rotational column goes beyond 2*pi and looks"
                                         : " rotational columns go beyond 2*pi and look")
              << " like degrees (" << FirstFew(suspicious)
              << "). If they are degrees, add the line inDegrees=yes before endheader\n";
  }
  return table;
}

void WarnUnusedColumns(const std::vector<std::string>& labels, const std::string& path,
                       const std::string& reason, bool strict) {
  if (labels.empty()) return;
  const std::string message = std::to_string(labels.size()) +
                              (labels.size() == 1 ? " column is" : " columns are") + " not used (" +
                              FirstFew(labels) + "): " + reason;
  if (strict) throw Error(SourceLocation{path, 0}, "", "--strict: " + message);
  std::cerr << "sinew: warning: " << path << ": " << message << "\n";
}

}  // namespace sinew::cli

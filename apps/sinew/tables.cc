#include "apps/sinew/tables.h"

#include <sinew/common/error.h>
#include <sinew/io/storage_labels.h>
#include <sinew/opensim/table_checks.h>

#include <algorithm>
#include <iostream>

#include "apps/sinew/notices.h"

namespace sinew::cli {

void CheckTable(const io::Storage& table, const std::string& path, const model::ModelSpec& spec) {
  for (const Diagnostic& warning : opensim::CheckTableFor(table, path, spec)) {
    std::cerr << "sinew: warning: " << warning.Format() << "\n";
  }
}

io::Storage ReadTableFor(const std::string& path, const model::ModelSpec& spec) {
  io::Storage table = io::ReadStorage(path);
  for (const Diagnostic& note : table.notes) std::cerr << "sinew: note: " << note.Format() << "\n";
  CheckTable(table, path, spec);
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

void PrintTableNotes(const Diagnostics& notes) {
  if (notes.empty()) return;
  std::cerr << "sinew: note: " << notes.size()
            << " coordinates or columns not matched between model and table; first: "
            << notes.front().Format() << "\n";
}

kinematics::MotionColumnMap MapMotionColumnsFor(const io::Storage& motion, const std::string& path,
                                                const model::ModelSpec& spec,
                                                const kinematics::CoordinateCouplers& couplers,
                                                const std::string& missing_means,
                                                const std::vector<std::string>& used_elsewhere) {
  kinematics::MotionColumnMap map = kinematics::MapMotionColumns(spec, motion.labels);
  // Speed columns (`q_u`, `.../speed`) are not used but do name a coordinate.
  std::vector<std::string> names, unknown;
  for (const model::CoordinateSpec& c : spec.coordinates) names.push_back(c.name);
  for (const std::string& label : map.unknown) {
    if (io::ParseColumnLabel(label, names)) continue;
    if (std::find(used_elsewhere.begin(), used_elsewhere.end(), label) != used_elsewhere.end()) {
      continue;
    }
    unknown.push_back(label);
  }
  WarnUnusedColumns(unknown, path, "they name no coordinate of the model");
  std::vector<std::string> missing;
  for (int c : map.missing) {
    if (spec.coordinates[c].joint != model::kNone && !couplers.Drives(c)) {
      missing.push_back(spec.coordinates[c].name);
    }
  }
  if (!missing.empty()) {
    std::cerr << "sinew: note: " << missing.size() << " coordinate(s) of the model are not in "
              << path << " (" << FirstFew(missing) << "); " << missing_means << "\n";
  }
  return map;
}

}  // namespace sinew::cli

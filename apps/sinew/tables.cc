#include "apps/sinew/tables.h"

#include <sinew/common/error.h>
#include <sinew/io/storage_labels.h>

#include <algorithm>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>

#include "apps/sinew/notices.h"

namespace sinew::cli {
namespace {

// What every command needs of a table before it makes poses from it: a finite, increasing time
// column and finite values in every column that names a coordinate (NaN would reach bodies.sto
// and the .glb). A repeated label is a warning: the first such column is the one used.
void CheckTable(const io::Storage& table, const std::string& path, const model::ModelSpec& spec) {
  const auto fail = [&path](const std::string& message) {
    throw Error(SourceLocation{path, 0}, "", message);
  };
  for (int row = 0; row < table.NumRows(); ++row) {
    const double t = table.time[row];
    if (!std::isfinite(t)) {
      fail("column '" + table.time_label + "', row " + std::to_string(row + 1) + ": " +
           ShowNumber(t) + " is not a finite time");
    }
    if (row > 0 && !(t > table.time[row - 1])) {
      fail("column '" + table.time_label + "' must increase, but row " + std::to_string(row + 1) +
           " has " + ShowNumber(t) + (t == table.time[row - 1] ? ", the same as" : ", less than") +
           " row " + std::to_string(row) + " (" + ShowNumber(table.time[row - 1]) + ")");
    }
  }
  std::map<std::string, int> first_column;
  std::vector<std::string> repeated;
  for (int column = 0; column < table.NumColumns(); ++column) {
    if (!first_column.emplace(table.labels[column], column).second) {
      repeated.push_back(table.labels[column]);
    }
  }
  if (!repeated.empty()) {
    std::cerr << "sinew: warning: " << path << ": " << repeated.size()
              << (repeated.size() == 1 ? " column label is" : " column labels are") << " repeated ("
              << FirstFew(repeated) << "); the first column of each is used\n";
  }
  std::vector<std::string> names;
  for (const model::CoordinateSpec& c : spec.coordinates) names.push_back(c.name);
  for (int column = 0; column < table.NumColumns(); ++column) {
    if (!io::ParseColumnLabel(table.labels[column], names)) continue;
    for (int row = 0; row < table.NumRows(); ++row) {
      const double value = table.Value(row, column);
      if (!std::isfinite(value)) {
        fail("column '" + table.labels[column] + "', row " + std::to_string(row + 1) + " (" +
             table.time_label + " " + ShowNumber(table.time[row]) + "): " + ShowNumber(value) +
             " is not a finite number, and the column names a coordinate");
      }
    }
  }
}

}  // namespace

io::Storage ReadTableFor(const std::string& path, const model::ModelSpec& spec) {
  io::Storage table = io::ReadStorage(path);
  for (const Diagnostic& note : table.notes) std::cerr << "sinew: note: " << note.Format() << "\n";
  CheckTable(table, path, spec);
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

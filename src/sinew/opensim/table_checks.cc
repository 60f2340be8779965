#include "sinew/opensim/table_checks.h"

#include <sinew/common/text.h>
#include <sinew/io/storage_labels.h>

#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <vector>

namespace sinew::opensim {
namespace {

// A warning about the whole file `path` (fields set one by one: g++ 12 warns of a braced one).
Diagnostic Warning(const std::string& path, std::string message) {
  Diagnostic warning;
  warning.where = {path, 0};
  warning.message = std::move(message);
  return warning;
}

void CheckTimes(const io::Storage& table, const std::string& path) {
  for (int row = 0; row < table.NumRows(); ++row) {
    const double t = table.time[row];
    if (!std::isfinite(t)) {
      throw Error({path, 0}, "",
                  "column '" + table.time_label + "', row " + std::to_string(row + 1) + ": " +
                      FormatNumber(t) + " is not a finite time");
    }
    if (row > 0 && !(t > table.time[row - 1])) {
      throw Error({path, 0}, "",
                  "column '" + table.time_label + "' must increase, but row " +
                      std::to_string(row + 1) + " has " + FormatNumber(t) +
                      (t == table.time[row - 1] ? ", the same as" : ", less than") + " row " +
                      std::to_string(row) + " (" + FormatNumber(table.time[row - 1]) + ")");
    }
  }
}

std::vector<std::string> CoordinateNames(const model::ModelSpec& spec, bool rotational_only) {
  std::vector<std::string> names;
  for (const model::CoordinateSpec& c : spec.coordinates) {
    if (!rotational_only || c.motion_type == model::MotionType::kRotational) {
      names.push_back(c.name);
    }
  }
  return names;
}

void CheckCoordinateValues(const io::Storage& table, const std::string& path,
                           const model::ModelSpec& spec) {
  const std::vector<std::string> names = CoordinateNames(spec, false);
  for (int column = 0; column < table.NumColumns(); ++column) {
    if (!io::ParseColumnLabel(table.labels[column], names)) continue;
    for (int row = 0; row < table.NumRows(); ++row) {
      const double value = table.Value(row, column);
      if (!std::isfinite(value)) {
        throw Error({path, 0}, "",
                    "column '" + table.labels[column] + "', row " + std::to_string(row + 1) + " (" +
                        table.time_label + " " + FormatNumber(table.time[row]) +
                        "): " + FormatNumber(value) +
                        " is not a finite number, and the column names a coordinate");
      }
    }
  }
}

std::optional<Diagnostic> RepeatedLabels(const io::Storage& table, const std::string& path) {
  std::map<std::string, int> first_column;
  std::vector<std::string> repeated;
  for (int column = 0; column < table.NumColumns(); ++column) {
    if (!first_column.emplace(table.labels[column], column).second) {
      repeated.push_back(table.labels[column]);
    }
  }
  if (repeated.empty()) return std::nullopt;
  return Warning(path, std::to_string(repeated.size()) +
                           (repeated.size() == 1 ? " column label is" : " column labels are") +
                           " repeated (" + FirstFew(repeated) +
                           "); the first column of each is used");
}

std::optional<Diagnostic> RadiansThatLookLikeDegrees(const io::Storage& table,
                                                     const std::string& path,
                                                     const model::ModelSpec& spec) {
  if (table.in_degrees_stated || table.in_degrees) return std::nullopt;
  const std::vector<std::string> rotational = CoordinateNames(spec, true);
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
  if (suspicious.empty()) return std::nullopt;
  return Warning(
      path, "no inDegrees line, so its angles are read as radians (as OpenSim reads them), but " +
                std::to_string(suspicious.size()) +
                (suspicious.size() == 1 ? " rotational column goes beyond 2*pi and looks"
                                        : " rotational columns go beyond 2*pi and look") +
                " like degrees (" + FirstFew(suspicious) +
                "). If they are degrees, add the line inDegrees=yes before endheader");
}

}  // namespace

Diagnostics CheckTableFor(const io::Storage& table, const std::string& path,
                          const model::ModelSpec& spec) {
  CheckTimes(table, path);
  CheckCoordinateValues(table, path, spec);
  Diagnostics warnings;
  if (auto repeated = RepeatedLabels(table, path)) warnings.push_back(*repeated);
  if (auto degrees = RadiansThatLookLikeDegrees(table, path, spec)) warnings.push_back(*degrees);
  return warnings;
}

}  // namespace sinew::opensim

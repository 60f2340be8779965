#include <sinew/io/storage_labels.h>

#include <algorithm>
#include <numbers>

namespace sinew::io {
namespace {

bool Contains(std::span<const std::string> names, std::string_view name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

bool EndsWith(std::string_view s, std::string_view suffix) {
  return s.size() >= suffix.size() && s.substr(s.size() - suffix.size()) == suffix;
}

// Multiplies the columns `is_rotational` accepts by `factor`.
void ScaleColumns(Storage& storage, const std::function<bool(std::string_view)>& is_rotational,
                  double factor) {
  for (int column = 0; column < storage.NumColumns(); ++column) {
    if (!is_rotational(storage.labels[column])) continue;
    for (int row = 0; row < storage.NumRows(); ++row) storage.Value(row, column) *= factor;
  }
}

}  // namespace

std::optional<CoordinateColumn> ParseColumnLabel(std::string_view label,
                                                 std::span<const std::string> coordinates) {
  if (label.empty() || label == "time") return std::nullopt;
  if (label.front() == '/') {
    // .../<coordinate>/value or .../<coordinate>/speed
    const size_t last_slash = label.rfind('/');
    const std::string_view last = label.substr(last_slash + 1);
    CoordinateColumn column;
    if (last == "value") {
      column.kind = CoordinateColumnKind::kValue;
    } else if (last == "speed") {
      column.kind = CoordinateColumnKind::kSpeed;
    } else {
      return std::nullopt;
    }
    if (last_slash == 0) return std::nullopt;
    const std::string_view path = label.substr(0, last_slash);
    const std::string_view name = path.substr(path.rfind('/') + 1);
    if (name.empty() || (!coordinates.empty() && !Contains(coordinates, name))) {
      return std::nullopt;
    }
    column.coordinate = std::string(name);
    column.path = std::string(path);
    return column;
  }
  if (!coordinates.empty()) {
    if (Contains(coordinates, label)) {
      return CoordinateColumn{std::string(label), CoordinateColumnKind::kValue, ""};
    }
    if (EndsWith(label, "_u") && Contains(coordinates, label.substr(0, label.size() - 2))) {
      return CoordinateColumn{std::string(label.substr(0, label.size() - 2)),
                              CoordinateColumnKind::kSpeed, ""};
    }
    return std::nullopt;
  }
  if (EndsWith(label, "_u") && label.size() > 2) {
    return CoordinateColumn{std::string(label.substr(0, label.size() - 2)),
                            CoordinateColumnKind::kSpeed, ""};
  }
  return CoordinateColumn{std::string(label), CoordinateColumnKind::kValue, ""};
}

int FindCoordinateColumn(const Storage& storage, std::string_view coordinate,
                         CoordinateColumnKind kind) {
  const std::string name(coordinate);
  const std::span<const std::string> names(&name, 1);
  for (int column = 0; column < storage.NumColumns(); ++column) {
    std::optional<CoordinateColumn> parsed = ParseColumnLabel(storage.labels[column], names);
    if (parsed && parsed->kind == kind) return column;
  }
  return -1;
}

void ConvertDegreesToRadians(Storage& storage,
                             const std::function<bool(std::string_view label)>& is_rotational) {
  if (!storage.in_degrees) return;
  ScaleColumns(storage, is_rotational, std::numbers::pi / 180.0);
  storage.in_degrees = false;
}

void ConvertDegreesToRadians(Storage& storage,
                             std::span<const std::string> rotational_coordinates) {
  ConvertDegreesToRadians(storage, [&](std::string_view label) {
    std::optional<CoordinateColumn> column = ParseColumnLabel(label, rotational_coordinates);
    return column.has_value();
  });
}

void ConvertRadiansToDegrees(Storage& storage,
                             const std::function<bool(std::string_view label)>& is_rotational) {
  if (storage.in_degrees) return;
  ScaleColumns(storage, is_rotational, 180.0 / std::numbers::pi);
  storage.in_degrees = true;
}

}  // namespace sinew::io

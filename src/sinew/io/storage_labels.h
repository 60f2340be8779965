// Column labels of OpenSim storage files and the degree/radian conversion of their columns.
#pragma once

#include <sinew/io/storage.h>

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace sinew::io {

/// What a column holds for a coordinate.
enum class CoordinateColumnKind { kValue, kSpeed };

/// A column label resolved to a coordinate.
struct CoordinateColumn {
  std::string coordinate;  ///< coordinate name, e.g. "knee_angle_r"
  CoordinateColumnKind kind = CoordinateColumnKind::kValue;
  std::string path;  ///< path-style labels: the coordinate's path ("/jointset/knee_r/knee_angle_r")
};

/// Maps a column label to a coordinate and whether the column is its value or its speed.
/// - Path style (OpenSim 4): `/jointset/knee_r/knee_angle_r/value` or `.../speed`: the segment
///   before the last is the coordinate. Other paths (`/forceset/soleus/activation`) give
///   nullopt.
/// - Old style: `knee_angle_r` is the value; `knee_angle_r_u` (OpenSim 3 state names) the speed.
/// When `coordinates` (the model's coordinate names) is not empty, only those names resolve:
/// an old-style label must equal a coordinate (value) or a coordinate + "_u" (speed), and a
/// path must name one. When it is empty, any old-style label other than `time` is taken for a
/// value unless it ends in "_u" (a heuristic: pass the names when you have a model).
std::optional<CoordinateColumn> ParseColumnLabel(std::string_view label,
                                                 std::span<const std::string> coordinates = {});

/// Index of the data column holding `coordinate`'s value (or speed), whichever label style the
/// file uses (`knee_angle_r` / `knee_angle_r_u` or `.../knee_angle_r/value` / `.../speed`);
/// -1 when absent. Exact names only: `coordinate` is matched as a name, not a heuristic.
int FindCoordinateColumn(const Storage& storage, std::string_view coordinate,
                         CoordinateColumnKind kind = CoordinateColumnKind::kValue);

/// Converts, when storage.in_degrees is set, every column whose label `is_rotational` accepts
/// from degrees to radians (values and speeds alike), then clears in_degrees. OpenSim converts
/// only rotational coordinates' columns; translations and everything else stay as they are.
/// Does nothing when in_degrees is false.
void ConvertDegreesToRadians(Storage& storage,
                             const std::function<bool(std::string_view label)>& is_rotational);

/// As above for the columns that ParseColumnLabel(label, rotational_coordinates) resolves, i.e.
/// the value and speed columns of the listed (the model's rotational) coordinates.
void ConvertDegreesToRadians(Storage& storage, std::span<const std::string> rotational_coordinates);

/// The inverse, for writing a file in degrees: converts the accepted columns from radians to
/// degrees and sets in_degrees. Does nothing when in_degrees is already set.
void ConvertRadiansToDegrees(Storage& storage,
                             const std::function<bool(std::string_view label)>& is_rotational);

}  // namespace sinew::io

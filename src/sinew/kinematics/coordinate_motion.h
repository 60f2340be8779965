// Coordinates from a motion table (.mot/.sto columns): which column drives which coordinate,
// and a row turned into the model's q. Coordinates missing from the table keep their values;
// unknown columns are reported, not fatal.
#pragma once

#include <sinew/model/model_spec.h>

#include <span>
#include <string>
#include <vector>

namespace sinew::kinematics {

/// How the columns of a motion table map to a model's coordinates.
struct MotionColumnMap {
  /// Per column: index into ModelSpec::coordinates, or kNone (time, speeds, unknown).
  std::vector<int> coordinate;
  /// Labels of columns that name no coordinate value of the model (excluding `time`).
  std::vector<std::string> unknown;
  /// Indices of the model's coordinates no column drives.
  std::vector<int> missing;
};

/// Maps labels to coordinates: old-style names (`knee_angle_r`) and OpenSim 4 paths
/// (`/jointset/knee_r/knee_angle_r/value`); `.../speed` columns are ignored silently.
MotionColumnMap MapMotionColumns(const model::ModelSpec& spec, std::span<const std::string> labels);

/// Writes the coordinates a row drives into `q` (ModelSpec::coordinates order), converting
/// degrees to radians for rotational coordinates when `in_degrees` (as OpenSim does; coupled
/// and translational coordinates are never converted). Other entries of `q` are untouched.
void ApplyMotionRow(const model::ModelSpec& spec, const MotionColumnMap& map,
                    std::span<const double> row, bool in_degrees, std::span<double> q);

}  // namespace sinew::kinematics

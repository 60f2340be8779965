// Body poses for visualization from a model's coordinates: the default pose, a motion or
// states table (.mot/.sto) frame by frame, or one instant of it.
#pragma once

#include <sinew/io/storage.h>
#include <sinew/model/model_spec.h>
#include <sinew/viz/body_motion.h>

#include <string>

namespace sinew::viz {

/// One frame at time 0 with every coordinate at its default value.
BodyMotion DefaultPoseMotion(const model::ModelSpec& spec);

/// Body poses at every row of `table` (coordinate values by name or OpenSim 4 state path;
/// degrees converted for rotational coordinates when the header says inDegrees=yes).
/// Coordinates the table does not drive stay at their default values; their names, and
/// table columns that name no coordinate, are appended to `notes`. Throws sinew::Error when
/// the table drives no coordinate at all or its times do not increase.
BodyMotion MotionFromTable(const model::ModelSpec& spec, const io::Storage& table,
                           Diagnostics* notes);

/// Body poses at time `t` (s): coordinates interpolated linearly between the two rows
/// around t. Unmatched columns and coordinates go to `notes` as in MotionFromTable. Throws
/// sinew::Error when t is outside the table's time range.
/// The one frame at time `t` (s), coordinates and body poses, as PosesAtTime.
BodyMotion MotionAtTime(const model::ModelSpec& spec, const io::Storage& table, double t,
                        Diagnostics* notes = nullptr);

std::vector<Transform> PosesAtTime(const model::ModelSpec& spec, const io::Storage& table, double t,
                                   Diagnostics* notes = nullptr);

}  // namespace sinew::viz

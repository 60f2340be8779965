// Motion and states tables (.mot/.sto) read for a model by the `sinew` commands, with ONE
// stderr line for each thing the reader or the model could not use as written.
#pragma once

#include <sinew/io/storage.h>
#include <sinew/kinematics/coordinate_couplers.h>
#include <sinew/kinematics/coordinate_motion.h>
#include <sinew/model/model_spec.h>

#include <string>
#include <vector>

namespace sinew::cli {

/// Checks `table`, read from `path`, for `spec` (opensim::CheckTableFor: a sinew::Error for
/// times and coordinate values that cannot be used), one stderr line per warning.
void CheckTable(const io::Storage& table, const std::string& path, const model::ModelSpec& spec);

/// Reads `path` for `spec` and checks it (opensim::CheckTableFor: errors for times and
/// coordinate values that cannot be used), printing the reader's notes and the check's warnings.
/// Throws sinew::Error for an unreadable file.
io::Storage ReadTableFor(const std::string& path, const model::ModelSpec& spec);

/// One warning line for the `labels` of table `path` that a command could not use: their
/// count, the first few, and `reason` ("they name no coordinate of the model"). With
/// `strict`, a sinew::Error instead (exit code 2). Nothing when `labels` is empty.
void WarnUnusedColumns(const std::vector<std::string>& labels, const std::string& path,
                       const std::string& reason, bool strict = false);

/// Maps the columns of `motion` (read from `path`) to the coordinates of `spec`, with one
/// warning line for the columns that name no coordinate (speed columns do name one) and one
/// note line for the coordinates of the model no column drives (a coupler's dependent
/// coordinates excepted: they follow their drivers); `missing_means` ends that note ("they keep
/// their default values"). Columns in `used_elsewhere` (e.g. muscle states another table reads)
/// are not reported.
kinematics::MotionColumnMap MapMotionColumnsFor(
    const io::Storage& motion, const std::string& path, const model::ModelSpec& spec,
    const kinematics::CoordinateCouplers& couplers, const std::string& missing_means,
    const std::vector<std::string>& used_elsewhere = {});

/// One note line for what a table and a model did not match (viz::MotionFromTable's or
/// viz::PosesAtTime's notes): their count and the first. Nothing when `notes` is empty.
void PrintTableNotes(const Diagnostics& notes);

}  // namespace sinew::cli

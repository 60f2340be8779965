// What every front end checks of a table (a states or motion file) before its rows become
// poses or a start state: `sinew` commands and Python's initial states alike.
#pragma once

#include <sinew/common/error.h>
#include <sinew/io/storage.h>
#include <sinew/model/model_spec.h>

#include <string>

namespace sinew::opensim {

/// Checks `table`, read from `path`, for `spec`. A time that is not finite or not increasing,
/// or a column naming a coordinate of `spec` with a NaN or infinite value (it would reach the
/// poses and the integrator), is a sinew::Error naming the file, the column and the row.
/// Returns the warnings: repeated column labels (the first column of each is used), and, when
/// the file has no inDegrees line, so that its angles are read as radians (as OpenSim reads
/// such a file), rotational coordinates whose values go beyond 2*pi in magnitude, which looks
/// like degrees.
Diagnostics CheckTableFor(const io::Storage& table, const std::string& path,
                          const model::ModelSpec& spec);

}  // namespace sinew::opensim

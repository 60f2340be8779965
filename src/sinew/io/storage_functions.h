// Functions of time fitted to the columns of a storage file, as OpenSim fits motions.
#pragma once

#include <sinew/functions/function.h>
#include <sinew/io/storage.h>

#include <vector>

namespace sinew::io {

/// One function of time per data column of `storage` (same order as storage.labels): the
/// interpolating natural spline of degree 2 * half_order - 1 through (time, value), i.e. what
/// OpenSim's GCVSplineSet(degree 5, storage) gives with error variance 0, which its tools use to
/// play a motion (values, speeds and accelerations then come from the spline's derivatives).
/// Convert degrees first (ConvertDegreesToRadians). Throws sinew::Error when there are fewer
/// than 2 * half_order rows or the times are not strictly increasing.
std::vector<functions::FunctionPtr> FitColumnSplines(const Storage& storage, int half_order = 3);

}  // namespace sinew::io

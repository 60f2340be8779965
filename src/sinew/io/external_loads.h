// OpenSim's ExternalLoads files (`<ExternalLoads>` with ExternalForce elements and a `datafile`)
// and the data an ExternalForce reads: the columns an identifier names, and the functions of
// time OpenSim fits through them.
#pragma once

#include <sinew/functions/function.h>
#include <sinew/io/storage.h>
#include <sinew/model/model_spec.h>

#include <string>
#include <string_view>
#include <vector>

namespace sinew::io {

/// What an ExternalLoads file says.
struct ExternalLoads {
  std::string file;       ///< The .xml file read.
  std::string name;       ///< Its `name` attribute ("" when absent).
  std::string data_file;  ///< `datafile` resolved: as written when absolute, else relative to
                          ///< the folder of `file` (OpenSim tries its working folder first).
  Storage data;           ///< The data file's table.
  /// Its ExternalForce elements, as force specs of class "ExternalForce" (path
  /// "/<name or externalloads>/<force>", appliesForce or the pre-4.0 isDisabled honoured),
  /// their properties kept in `element` for the force builder.
  std::vector<model::ForceSpec> forces;
  /// What was read leniently (e.g. the 3.x kinematics options OpenSim 4 ignores).
  Diagnostics notes;
};

/// Reads an ExternalLoads file (OpenSim 2.3.1 and later: ExternalForce elements) and its data
/// file. Throws sinew::Error naming the file and line for a malformed file, a missing or empty
/// `datafile`, a data file that cannot be read, an element that is not an ExternalForce, or
/// the pre-2.3.1 form (PrescribedForce elements naming columns).
ExternalLoads ReadExternalLoads(const std::string& file);

/// An ExternalForce identifier is unset when absent, blank or "Unassigned" (OpenSim's
/// appliesForce / specifiesPoint / appliesTorque).
bool IsIdentifierSet(std::string_view identifier);

/// The data columns whose label begins with `identifier` (OpenSim's
/// Storage::getColumnIndicesForIdentifier), in file order. An ExternalForce needs exactly 3.
std::vector<int> FindIdentifierColumns(const Storage& data, std::string_view identifier);

/// The function of time OpenSim's ExternalForce fits through data column `column`: with one
/// row a Constant, with 2 or 3 rows a PiecewiseLinearFunction, with more the interpolating
/// natural cubic GCVSpline (degree 3, error variance 0). Throws sinew::Error when the times do
/// not increase strictly (the spline needs distinct knots).
functions::FunctionPtr FitExternalForceColumn(const Storage& data, int column);

}  // namespace sinew::io

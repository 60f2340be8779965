// OpenSim storage files (.sto, .mot): a header ending in `endheader`, a line of column labels,
// then rows of numbers. The first column is the independent variable (normally `time`).
#pragma once

#include <sinew/common/error.h>

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace sinew::io {

/// The contents of a .sto/.mot file. Values are stored row-major.
struct Storage {
  /// The header's first line when it is not a key=value pair (OpenSim writes the table's name).
  std::string name;
  /// Every key=value header line except nRows, nColumns and inDegrees, in file order
  /// (e.g. version=1, DataType=double, OpenSimVersion=4.0). Keys and values are trimmed.
  std::vector<std::pair<std::string, std::string>> metadata;
  /// Other header lines (free text, SIMM header lines), trimmed, blank ones dropped.
  std::vector<std::string> comments;
  /// Angles in the file are in degrees: the header's inDegrees flag or, when the header has
  /// none, what OpenSim's Storage reader assumes (see in_degrees_stated).
  bool in_degrees = false;
  /// True when the header states the unit: an inDegrees line, or in an old file (no version
  /// line, or version=0) the SIMM line "Angles are in degrees." / "Angles are in radians.".
  /// Otherwise OpenSim's rule applies: an old .mot file is a SIMM motion, in degrees; anything
  /// else is in radians. (OpenSim reads an old .mot as degrees even under inDegrees=no; Sinew
  /// follows a stated unit.)
  bool in_degrees_stated = false;
  /// Label of the first column, normally "time".
  std::string time_label = "time";
  /// Labels of the data columns after the first.
  std::vector<std::string> labels;
  /// The first column, one entry per row.
  std::vector<double> time;
  /// The data columns: values[row * labels.size() + column].
  std::vector<double> values;
  /// Things read leniently, as OpenSim does (nRows or nColumns disagreeing with the data).
  Diagnostics notes;

  int NumRows() const { return static_cast<int>(time.size()); }
  int NumColumns() const { return static_cast<int>(labels.size()); }
  double Value(int row, int column) const { return values[row * labels.size() + column]; }
  double& Value(int row, int column) { return values[row * labels.size() + column]; }
  /// Index of the data column labelled `label`, or -1.
  int FindColumn(std::string_view label) const;
  /// A copy of the data column `column`.
  std::vector<double> Column(int column) const;
  /// Appends a row; `row` must have NumColumns() entries (throws sinew::Error otherwise).
  void AppendRow(double t, const std::vector<double>& row);
  /// The value of metadata `key`, or "" when absent.
  std::string Metadata(std::string_view key) const;
};

/// Reads a .sto or .mot file. Labels are tab-separated (empty labels between repeated tabs are
/// skipped, as OpenSim does; a label line without tabs is split on spaces); rows are separated
/// by tabs or spaces. nRows and nColumns are checked against the data and a disagreement is
/// noted in Storage::notes, not fatal (OpenSim's own files disagree sometimes). A row whose
/// length differs from the label count, a bad number, a DataType other than double (OpenSim 4's
/// Vec3/Quaternion tables are not supported), or a missing `endheader` throws
/// sinew::Error naming file and line.
Storage ReadStorage(const std::string& file);

/// As ReadStorage, from text in memory; `file` names it in messages.
Storage ParseStorage(std::string_view text, const std::string& file);

/// Writes `storage` in OpenSim's layout: name line ("UNKNOWN" when empty), version=1 (unless
/// metadata has a version), nRows, nColumns (including time), inDegrees, remaining metadata,
/// endheader, tab-separated labels, then tab-separated rows. Numbers are written in the shortest
/// form that reads back to the same double (full precision). The file is written atomically
/// (sinew::WriteFileAtomically: complete or not at all, a symbolic link replaced, not followed).
/// Throws sinew::Error if the file cannot be written.
void WriteStorage(const Storage& storage, const std::string& file);

/// The text WriteStorage writes.
std::string FormatStorage(const Storage& storage);

}  // namespace sinew::io

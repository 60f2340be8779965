#include <sinew/common/atomic_file.h>
#include <sinew/io/internal/number_text.h>
#include <sinew/io/storage.h>

#include <cctype>
#include <charconv>
#include <fstream>
#include <sstream>
#include <system_error>

namespace sinew::io {
namespace {

bool IsBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

std::string_view Trim(std::string_view s) {
  while (!s.empty() && IsBlank(s.front())) s.remove_prefix(1);
  while (!s.empty() && IsBlank(s.back())) s.remove_suffix(1);
  return s;
}

bool EqualsIgnoringCase(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(a[i])) !=
        std::tolower(static_cast<unsigned char>(b[i]))) {
      return false;
    }
  }
  return true;
}

// Splits on any run of spaces and tabs.
std::vector<std::string_view> SplitBlanks(std::string_view line) {
  std::vector<std::string_view> tokens;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && IsBlank(line[i])) ++i;
    const size_t start = i;
    while (i < line.size() && !IsBlank(line[i])) ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
  }
  return tokens;
}

// Labels: tab-separated (labels may contain spaces), empty fields skipped.
std::vector<std::string> SplitLabels(std::string_view line) {
  std::vector<std::string> labels;
  if (line.find('\t') == std::string_view::npos) {
    for (std::string_view token : SplitBlanks(line)) labels.emplace_back(token);
    return labels;
  }
  size_t start = 0;
  while (start <= line.size()) {
    size_t end = line.find('\t', start);
    if (end == std::string_view::npos) end = line.size();
    std::string_view field = Trim(line.substr(start, end - start));
    if (!field.empty()) labels.emplace_back(field);
    start = end + 1;
  }
  return labels;
}

// Parses a number as OpenSim writes them (also nan/inf and a leading '+').
bool ParseNumber(std::string_view token, double* value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const char* end = token.data() + token.size();
  auto [ptr, ec] = std::from_chars(token.data(), end, *value);
  return ec == std::errc() && ptr == end;
}

// The file's version=N (OpenSim reads it with atoi: 0 when absent or not a number).
int FileVersion(const Storage& storage) {
  const std::string version = storage.Metadata("version");
  int number = 0;
  std::from_chars(version.data(), version.data() + version.size(), number);
  return number;
}

// What OpenSim's Storage reader takes the angles of a file without an inDegrees line to be:
// an old file (version < 1) may say it in SIMM's words; an old .mot file is a SIMM motion, in
// degrees; anything else is in radians (OpenSim's default).
void ApplyOpenSimAngleRule(Storage& storage, const std::string& simm_angles_line,
                           const std::string& file) {
  if (FileVersion(storage) >= 1) return;
  if (!simm_angles_line.empty()) {
    storage.in_degrees_stated = true;
    storage.in_degrees = simm_angles_line == "Angles are in degrees.";
    return;
  }
  const std::string extension = file.size() >= 4 ? file.substr(file.size() - 4) : "";
  if (EqualsIgnoringCase(extension, ".mot")) {
    storage.in_degrees = true;
    Diagnostic note;
    note.where.file = file;
    note.message =
        "no inDegrees line in an old-format .mot file (no version=1): its angles are read as "
        "degrees, as OpenSim reads a SIMM motion";
    storage.notes.push_back(std::move(note));
  }
}

}  // namespace

int Storage::FindColumn(std::string_view label) const {
  for (size_t i = 0; i < labels.size(); ++i) {
    if (labels[i] == label) return static_cast<int>(i);
  }
  return -1;
}

std::vector<double> Storage::Column(int column) const {
  std::vector<double> result(time.size());
  for (int row = 0; row < NumRows(); ++row) result[row] = Value(row, column);
  return result;
}

void Storage::AppendRow(double t, const std::vector<double>& row) {
  if (row.size() != labels.size()) {
    throw Error("Storage::AppendRow: expected " + std::to_string(labels.size()) + " values, got " +
                std::to_string(row.size()));
  }
  time.push_back(t);
  values.insert(values.end(), row.begin(), row.end());
}

std::string Storage::Metadata(std::string_view key) const {
  for (const auto& [k, v] : metadata) {
    if (k == key) return v;
  }
  return "";
}

Storage ParseStorage(std::string_view text, const std::string& file) {
  Storage storage;
  int line_number = 0;
  size_t position = 0;
  // Returns false at the end of the text.
  auto next_line = [&](std::string_view* line) {
    if (position >= text.size()) return false;
    size_t end = text.find('\n', position);
    if (end == std::string_view::npos) end = text.size();
    *line = text.substr(position, end - position);
    position = end + 1;
    ++line_number;
    return true;
  };
  auto fail = [&](const std::string& message) -> void {
    throw Error(SourceLocation{file, line_number}, "", message);
  };

  // Header.
  long declared_rows = -1, declared_columns = -1;
  std::string simm_angles_line;
  int rows_line = 0, columns_line = 0;
  std::string_view line;
  bool found_end = false;
  while (next_line(&line)) {
    std::string_view trimmed = Trim(line);
    if (trimmed == "endheader") {
      found_end = true;
      break;
    }
    const size_t equals = trimmed.find('=');
    if (equals == std::string_view::npos) {
      if (trimmed == "Angles are in degrees." || trimmed == "Angles are in radians.") {
        simm_angles_line = std::string(trimmed);
      }
      if (line_number == 1) {
        storage.name = std::string(trimmed);
      } else if (!trimmed.empty()) {
        storage.comments.emplace_back(trimmed);
      }
      continue;
    }
    const std::string key(Trim(trimmed.substr(0, equals)));
    const std::string value(Trim(trimmed.substr(equals + 1)));
    if (key == "nRows" || key == "nColumns") {
      double number = 0;
      // Written as a negation so that NaN fails too; the bound keeps the cast below defined.
      if (!ParseNumber(value, &number) || !(number >= 0 && number < 1e18)) {
        fail(key + " expects a count, found '" + value + "'");
      }
      (key == "nRows" ? declared_rows : declared_columns) = static_cast<long>(number);
      (key == "nRows" ? rows_line : columns_line) = line_number;
    } else if (key == "inDegrees") {
      storage.in_degrees_stated = true;
      if (EqualsIgnoringCase(value, "yes") || EqualsIgnoringCase(value, "true")) {
        storage.in_degrees = true;
      } else if (EqualsIgnoringCase(value, "no") || EqualsIgnoringCase(value, "false")) {
        storage.in_degrees = false;
      } else {
        fail("inDegrees expects yes or no, found '" + value + "'");
      }
    } else {
      if (key == "DataType" && value != "double") {
        fail("DataType=" + value + " tables are not supported (only double columns)");
      }
      storage.metadata.emplace_back(key, value);
    }
  }
  if (!found_end) fail("no 'endheader' line: not an OpenSim storage file");
  if (!storage.in_degrees_stated) ApplyOpenSimAngleRule(storage, simm_angles_line, file);

  // Labels: the first non-blank line after the header.
  std::vector<std::string> labels;
  while (labels.empty()) {
    if (!next_line(&line)) fail("no column labels after 'endheader'");
    labels = SplitLabels(line);
  }
  storage.time_label = labels.front();
  storage.labels.assign(labels.begin() + 1, labels.end());
  const size_t width = labels.size();

  // Rows.
  while (next_line(&line)) {
    std::vector<std::string_view> tokens = SplitBlanks(line);
    if (tokens.empty()) continue;
    if (tokens.size() != width) {
      fail("row has " + std::to_string(tokens.size()) + " values but there are " +
           std::to_string(width) + " column labels");
    }
    for (size_t i = 0; i < width; ++i) {
      double value = 0;
      if (!ParseNumber(tokens[i], &value)) {
        fail("column '" + labels[i] + "': expected a number, found '" + std::string(tokens[i]) +
             "'");
      }
      if (i == 0) {
        storage.time.push_back(value);
      } else {
        storage.values.push_back(value);
      }
    }
  }
  if (declared_rows >= 0 && declared_rows != storage.NumRows()) {
    storage.notes.push_back({{file, rows_line},
                             "",
                             "nRows=" + std::to_string(declared_rows) + " but the file has " +
                                 std::to_string(storage.NumRows()) + " rows"});
  }
  if (declared_columns >= 0 && declared_columns != static_cast<long>(width)) {
    storage.notes.push_back({{file, columns_line},
                             "",
                             "nColumns=" + std::to_string(declared_columns) + " but the file has " +
                                 std::to_string(width) + " column labels"});
  }
  return storage;
}

Storage ReadStorage(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(SourceLocation{file, 0}, "", "cannot open file");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return ParseStorage(buffer.str(), file);
}

std::string FormatStorage(const Storage& storage) {
  std::string out;
  out += storage.name.empty() ? "UNKNOWN" : storage.name;
  out += '\n';
  if (storage.Metadata("version").empty()) out += "version=1\n";
  out += "nRows=" + std::to_string(storage.NumRows()) + "\n";
  out += "nColumns=" + std::to_string(storage.NumColumns() + 1) + "\n";
  out += std::string("inDegrees=") + (storage.in_degrees ? "yes" : "no") + "\n";
  for (const auto& [key, value] : storage.metadata) out += key + "=" + value + "\n";
  for (const std::string& comment : storage.comments) out += comment + "\n";
  out += "endheader\n";
  out += storage.time_label;
  for (const std::string& label : storage.labels) out += "\t" + label;
  // A label line without tabs is split on blanks when read: a lone time label with a blank in it
  // gets a trailing tab (an empty field, skipped on reading) to be read back whole.
  if (storage.labels.empty() && storage.time_label.find_first_of(" \t\r") != std::string::npos) {
    out += '\t';
  }
  out += '\n';
  for (int row = 0; row < storage.NumRows(); ++row) {
    internal::AppendNumber(out, storage.time[row]);
    for (int column = 0; column < storage.NumColumns(); ++column) {
      out += '\t';
      internal::AppendNumber(out, storage.Value(row, column));
    }
    out += '\n';
  }
  return out;
}

void WriteStorage(const Storage& storage, const std::string& file) {
  WriteFileAtomically(file, FormatStorage(storage));
}

}  // namespace sinew::io

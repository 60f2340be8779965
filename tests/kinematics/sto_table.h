// A minimal, test-only reader of OpenSim .sto/.mot tables (header up to `endheader`, a label
// line, numeric rows), so the kinematics tests read their reference files independently of
// the storage code under test elsewhere.
#pragma once

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace sinew::testing {

/// A numeric table: column labels (first is usually "time") and rows.
struct StoTable {
  std::vector<std::string> labels;
  std::vector<std::vector<double>> rows;
  bool in_degrees = false;

  /// Index of `label`, or -1.
  int Column(const std::string& label) const {
    for (size_t i = 0; i < labels.size(); ++i) {
      if (labels[i] == label) return static_cast<int>(i);
    }
    return -1;
  }
};

/// Reads `path`; throws std::runtime_error when the file is missing or malformed.
inline StoTable ReadStoTable(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  StoTable t;
  std::string line;
  bool header_done = false;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.rfind("inDegrees=", 0) == 0) t.in_degrees = line.find("yes") != std::string::npos;
    if (line == "endheader") {
      header_done = true;
      break;
    }
  }
  if (!header_done || !std::getline(in, line)) throw std::runtime_error("no header: " + path);
  std::istringstream labels(line);
  for (std::string label; labels >> label;) t.labels.push_back(label);
  while (std::getline(in, line)) {
    std::istringstream values(line);
    std::vector<double> row;
    for (double v; values >> v;) row.push_back(v);
    if (row.empty()) continue;
    if (row.size() != t.labels.size()) throw std::runtime_error("ragged row in " + path);
    t.rows.push_back(std::move(row));
  }
  return t;
}

}  // namespace sinew::testing

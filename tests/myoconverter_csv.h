// MyoConverter's reference tables (`reference-csv/<Model>/*.csv`): '#' comment lines, a header
// line, then comma-separated rows.
#pragma once

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace sinew::testing {

/// The rows of a MyoConverter csv, each split at its commas (comments and header left out).
inline std::vector<std::vector<std::string>> ReadMyoConverterCsv(const std::string& file) {
  std::ifstream in(file);
  EXPECT_TRUE(in.good()) << file;
  std::vector<std::vector<std::string>> rows;
  std::string line;
  bool header = true;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (header) {
      header = false;
      continue;
    }
    std::vector<std::string> fields;
    std::stringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) fields.push_back(cell);
    rows.push_back(fields);
  }
  return rows;
}

}  // namespace sinew::testing

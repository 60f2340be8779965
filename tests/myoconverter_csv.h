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

/// One row of a MyoConverter muscle_kinetics.csv: OpenSim's equilibrium fiber forces (N) of a
/// muscle at an activation and the musculotendon length (m) of a pose.
struct MuscleKineticsRow {
  std::string muscle, pose;
  double activation, mtu_length, active_force, passive_force, total_force;
};

/// The rows of a muscle_kinetics.csv
/// ("muscle,activation,pose,mtu_length,active_force,passive_force,total_force").
inline std::vector<MuscleKineticsRow> ReadMuscleKinetics(const std::string& file) {
  std::vector<MuscleKineticsRow> rows;
  for (const std::vector<std::string>& f : ReadMyoConverterCsv(file)) {
    EXPECT_EQ(f.size(), 7u);
    if (f.size() != 7) continue;
    rows.push_back({f[0], f[2], std::stod(f[1]), std::stod(f[3]), std::stod(f[4]), std::stod(f[5]),
                    std::stod(f[6])});
  }
  return rows;
}

}  // namespace sinew::testing

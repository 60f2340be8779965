// `sinew kinematics MODEL.osim [--motion FILE] --out DIR`: body mass-centre positions and
// orientations (OpenSim BodyKinematics layout) and marker locations, at the default pose or for
// every row of a motion file.
#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "apps/sinew/commands.h"
#include "common/error.h"
#include "io/osim_reader.h"
#include "kinematics/body_kinematics.h"
#include "kinematics/coordinate_motion.h"
#include "kinematics/forward_kinematics.h"
#include "kinematics/kinematic_tree.h"

namespace sinew::cli {
namespace {

// ---- Minimal .sto/.mot table I/O, TEMPORARY: owned by the functions branch (src/io/storage.h)
// ---- once it lands; kept here so the command works meanwhile.
struct Table {
  std::vector<std::string> labels;
  std::vector<std::vector<double>> rows;
  bool in_degrees = false;
};

Table ReadTable(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw Error(SourceLocation{file, 0}, "", "cannot open motion file");
  Table t;
  std::string line;
  int line_number = 0;
  bool header_done = false;
  while (std::getline(in, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.rfind("inDegrees=", 0) == 0) t.in_degrees = line.find("yes") != std::string::npos;
    if (line == "endheader") {
      header_done = true;
      break;
    }
  }
  if (!header_done) throw Error(SourceLocation{file, line_number}, "", "no 'endheader' line");
  if (!std::getline(in, line)) throw Error(SourceLocation{file, line_number}, "", "no labels");
  ++line_number;
  std::istringstream labels(line);
  for (std::string label; labels >> label;) t.labels.push_back(label);
  while (std::getline(in, line)) {
    ++line_number;
    std::istringstream values(line);
    std::vector<double> row;
    std::string token;
    while (values >> token) {
      try {
        size_t used = 0;
        row.push_back(std::stod(token, &used));
        if (used != token.size()) throw std::invalid_argument(token);
      } catch (const std::exception&) {
        throw Error(SourceLocation{file, line_number}, "", "not a number: '" + token + "'");
      }
    }
    if (row.empty()) continue;
    if (row.size() != t.labels.size()) {
      throw Error(SourceLocation{file, line_number}, "",
                  fmt::format("{} values for {} columns", row.size(), t.labels.size()));
    }
    t.rows.push_back(std::move(row));
  }
  return t;
}

void WriteTable(const std::string& file, const std::string& name, const Table& t) {
  std::ofstream out(file);
  if (!out) throw Error(SourceLocation{file, 0}, "", "cannot write file");
  out << name << "\nversion=1\nnRows=" << t.rows.size() << "\nnColumns=" << t.labels.size()
      << "\ninDegrees=" << (t.in_degrees ? "yes" : "no") << "\nendheader\n";
  for (size_t i = 0; i < t.labels.size(); ++i) out << (i ? "\t" : "") << t.labels[i];
  out << "\n";
  for (const auto& row : t.rows) {
    for (size_t i = 0; i < row.size(); ++i)
      out << (i ? "\t" : "") << fmt::format("{:.17g}", row[i]);
    out << "\n";
  }
}
// ---- end of the temporary table I/O.

struct Options {
  std::string model;
  std::string motion;
  std::string out;
};

void Run(const Options& options) {
  const ModelSpec spec = ReadOsim(options.model);
  const KinematicTree tree(spec);
  std::vector<double> q = tree.default_q();
  std::vector<Transform> X_GB(tree.num_bodies());

  Table motion;
  MotionColumnMap map;
  if (!options.motion.empty()) {
    motion = ReadTable(options.motion);
    map = MapMotionColumns(spec, motion.labels);
    for (const std::string& label : map.unknown) {
      std::cerr << "sinew: warning: " << options.motion << ": column '" << label
                << "' names no coordinate of the model; ignored\n";
    }
    for (int c : map.missing) {
      std::cerr << "sinew: note: coordinate '" << spec.coordinates[c].name
                << "' is not in the motion; it keeps its default value\n";
    }
  } else {
    motion.labels = {"time"};
    motion.rows = {{0.0}};
  }
  const int time_column = [&] {
    for (size_t i = 0; i < motion.labels.size(); ++i) {
      if (motion.labels[i] == "time") return static_cast<int>(i);
    }
    return -1;
  }();

  Table bodies, markers;
  bodies.labels = {"time"};
  for (const std::string& l : BodyKinematicsLabels(spec)) bodies.labels.push_back(l);
  markers.labels = {"time"};
  for (const std::string& l : MarkerLocationLabels(spec)) markers.labels.push_back(l);
  for (size_t r = 0; r < motion.rows.size(); ++r) {
    const std::vector<double>& row = motion.rows[r];
    if (!options.motion.empty()) ApplyMotionRow(spec, map, row, motion.in_degrees, q);
    CalcBodyPoses(tree, q, X_GB);
    const double time = time_column >= 0 ? row[time_column] : static_cast<double>(r);
    std::vector<double> b = {time}, m = {time};
    for (double v : CalcBodyKinematicsRow(spec, X_GB)) b.push_back(v);
    for (double v : CalcMarkerLocationRow(spec, X_GB)) m.push_back(v);
    bodies.rows.push_back(std::move(b));
    markers.rows.push_back(std::move(m));
  }

  std::error_code ec;
  std::filesystem::create_directories(options.out, ec);
  if (ec)
    throw Error(SourceLocation{options.out, 0}, "", "cannot create directory: " + ec.message());
  const std::filesystem::path dir(options.out);
  // OpenSim writes BodyKinematics angles in degrees with inDegrees=no; we say what they are.
  bodies.in_degrees = true;
  WriteTable((dir / "bodies.sto").string(), "Positions", bodies);
  if (!spec.markers.empty()) {
    WriteTable((dir / "markers.sto").string(), "Model Marker Locations", markers);
  }
}

}  // namespace

void AddKinematicsCommand(CLI::App& app) {
  auto options = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "kinematics", "Body positions/orientations and marker locations from coordinate values");
  cmd->add_option("model", options->model, "OpenSim model (.osim)")->required();
  cmd->add_option("--motion", options->motion,
                  "Coordinates over time (.mot/.sto); without it, one row at the default pose");
  cmd->add_option("--out", options->out, "Output directory (bodies.sto, markers.sto)")->required();
  cmd->callback([options] { Run(*options); });
}

}  // namespace sinew::cli

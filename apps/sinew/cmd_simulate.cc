// `sinew simulate MODEL.osim --duration T [--accuracy A] [--integrator NAME] [--step H]
//  [--report-interval DT] [--initial-states FILE.sto] [--quiet] --out DIR`: a passive forward
// simulation of the model's skeleton. Writes DIR/states.sto (every coordinate's value and speed,
// OpenSim 4 labels, radians and metres) and DIR/bodies.sto (OpenSim BodyKinematics positions).
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "apps/sinew/commands.h"
#include "build/build_system.h"
#include "common/error.h"
#include "engine/assemble.h"
#include "engine/integrator.h"
#include "engine/pose.h"
#include "io/osim_reader.h"
#include "kinematics/body_kinematics.h"
#include "kinematics/coordinate_motion.h"

namespace sinew::cli {
namespace {

struct SimulateOptions {
  std::string model;
  double duration = 0.0;
  double accuracy = 1e-6;
  std::string integrator = "rk45";
  double step = 0.0;
  double report_interval = 0.01;
  std::string initial_states;
  std::string out;
  bool quiet = false;
};

// A table of rows, written as an OpenSim storage file (tab separated, header, endheader).
struct Table {
  std::vector<std::string> labels;  // time first
  std::vector<std::vector<double>> rows;
};

void WriteTable(const std::string& path, const std::string& name, const Table& table,
                bool in_degrees) {
  std::ofstream out(path);
  if (!out) throw Error({path, 0}, "", "cannot write the file");
  out << name << "\nversion=1\nnRows=" << table.rows.size() << "\nnColumns=" << table.labels.size()
      << "\ninDegrees=" << (in_degrees ? "yes" : "no") << "\nendheader\n";
  for (size_t i = 0; i < table.labels.size(); ++i) out << (i ? "\t" : "") << table.labels[i];
  out << "\n";
  char buffer[32];
  for (const auto& row : table.rows) {
    for (size_t i = 0; i < row.size(); ++i) {
      std::snprintf(buffer, sizeof buffer, "%.17g", row[i]);
      out << (i ? "\t" : "") << buffer;
    }
    out << "\n";
  }
  if (!out) throw Error({path, 0}, "", "error while writing the file");
}

// Reads a storage file's labels, first data row and inDegrees flag (minimal reader).
Table ReadFirstRow(const std::string& path, bool* in_degrees) {
  std::ifstream in(path);
  if (!in) throw Error({path, 0}, "", "cannot open the initial-states file");
  std::string line;
  int line_number = 0;
  *in_degrees = false;
  bool header_done = false;
  while (std::getline(in, line)) {
    ++line_number;
    if (line.rfind("inDegrees", 0) == 0) *in_degrees = line.find("yes") != std::string::npos;
    if (line.rfind("endheader", 0) == 0) {
      header_done = true;
      break;
    }
  }
  if (!header_done) throw Error({path, line_number}, "", "no 'endheader' line");
  Table table;
  if (!std::getline(in, line)) throw Error({path, line_number}, "", "no column labels");
  ++line_number;
  {
    std::istringstream ls(line);
    std::string label;
    while (ls >> label) table.labels.push_back(label);
  }
  if (table.labels.empty() || table.labels[0] != "time") {
    throw Error({path, line_number}, "", "the first column must be 'time'");
  }
  while (std::getline(in, line)) {
    ++line_number;
    std::istringstream ls(line);
    std::vector<double> row;
    double x;
    while (ls >> x) row.push_back(x);
    if (row.empty()) continue;
    if (row.size() != table.labels.size()) {
      throw Error({path, line_number}, "",
                  "row has " + std::to_string(row.size()) + " values for " +
                      std::to_string(table.labels.size()) + " columns");
    }
    table.rows.push_back(std::move(row));
    break;
  }
  if (table.rows.empty()) throw Error({path, line_number}, "", "no data rows");
  return table;
}

// Sets q and u from the first row of an initial-states file (OpenSim 4 paths or old names).
void ApplyInitialStates(const std::string& path, const ModelSpec& spec,
                        const engine::System& system, engine::State& state) {
  bool in_degrees = false;
  const Table table = ReadFirstRow(path, &in_degrees);
  const std::vector<double>& row = table.rows[0];
  state.t = row[0];
  std::vector<double> q(state.q.data(), state.q.data() + state.q.size());
  const MotionColumnMap map = MapMotionColumns(spec, table.labels);
  ApplyMotionRow(spec, map, row, in_degrees, q);
  for (size_t c = 0; c < q.size(); ++c) state.q[c] = q[c];
  for (int c = 0; c < system.num_coordinates(); ++c) {
    const CoordinateSpec& coordinate = spec.coordinates[c];
    const std::string path4 =
        "/jointset/" + spec.joints[coordinate.joint].name + "/" + coordinate.name + "/speed";
    for (size_t i = 1; i < table.labels.size(); ++i) {
      if (table.labels[i] == coordinate.name + "_u" || table.labels[i] == path4 ||
          table.labels[i] == coordinate.name + "_speed") {
        const bool degrees = in_degrees && coordinate.motion_type == MotionType::kRotational;
        state.u[c] = degrees ? row[i] * M_PI / 180.0 : row[i];
      }
    }
  }
  engine::PlaceBodies(system, state);
  engine::ProjectState(system, state);
}

void ShowProgress(double fraction, double t) {
  const int width = 40;
  const int filled = static_cast<int>(fraction * width);
  std::fprintf(stderr, "\r[%s%s] %3d%%  t = %.3f s", std::string(filled, '#').c_str(),
               std::string(width - filled, ' ').c_str(), static_cast<int>(100 * fraction), t);
  std::fflush(stderr);
}

void RunSimulate(const SimulateOptions& options) {
  if (!(options.duration >= 0.0)) throw Error("--duration must be >= 0");
  if (!(options.report_interval > 0.0)) throw Error("--report-interval must be > 0");
  const ModelSpec spec = ReadOsim(options.model);
  const std::unique_ptr<engine::System> system = BuildSystem(spec);
  engine::State state = engine::MakeDefaultState(*system);
  if (!options.initial_states.empty()) {
    ApplyInitialStates(options.initial_states, spec, *system, state);
  }
  engine::IntegratorSettings settings;
  settings.accuracy = options.accuracy;
  settings.step = options.step;
  const auto integrator = engine::MakeIntegrator(options.integrator, *system, settings);
  std::filesystem::create_directories(options.out);

  Table states, bodies;
  states.labels.push_back("time");
  for (const CoordinateSpec& c : spec.coordinates) {
    const std::string base = "/jointset/" + spec.joints[c.joint].name + "/" + c.name;
    states.labels.push_back(base + "/value");
    states.labels.push_back(base + "/speed");
  }
  bodies.labels.push_back("time");
  for (const std::string& label : BodyKinematicsLabels(spec)) bodies.labels.push_back(label);
  std::vector<Transform> X_GB(system->num_bodies());
  auto record = [&]() {
    std::vector<double> row{state.t};
    for (int c = 0; c < system->num_coordinates(); ++c) {
      row.push_back(state.q[c]);
      row.push_back(state.u[c]);
    }
    states.rows.push_back(std::move(row));
    for (int b = 0; b < system->num_bodies(); ++b) X_GB[b] = engine::PoseOf(state.bodies[b]);
    std::vector<double> body_row{state.t};
    for (double x : CalcBodyKinematicsRow(spec, X_GB)) body_row.push_back(x);
    bodies.rows.push_back(std::move(body_row));
  };

  const bool progress = !options.quiet && isatty(fileno(stderr));
  const double t0 = state.t, t_end = state.t + options.duration;
  const long n = static_cast<long>(std::ceil(options.duration / options.report_interval - 1e-9));
  record();
  for (long i = 1; i <= n; ++i) {
    const double t = std::min(t0 + i * options.report_interval, t_end);
    integrator->StepTo(state, t);
    record();
    if (progress) ShowProgress(static_cast<double>(i) / n, state.t);
  }
  if (progress) std::fprintf(stderr, "\n");
  WriteTable(options.out + "/states.sto", "states", states, false);
  // BodyKinematics rows give angles in degrees.
  WriteTable(options.out + "/bodies.sto", "bodies", bodies, true);
  if (!options.quiet) {
    const auto& stats = integrator->stats();
    std::cout << "simulated " << options.duration << " s of " << spec.name << ": " << stats.steps
              << " steps (" << stats.rejected << " rejected), " << stats.evaluations
              << " evaluations; wrote " << options.out << "/states.sto and bodies.sto\n";
  }
}

}  // namespace

void AddSimulateCommand(CLI::App& app) {
  auto options = std::make_shared<SimulateOptions>();
  CLI::App* cmd =
      app.add_subcommand("simulate", "Passive forward simulation of a model's skeleton");
  cmd->add_option("model", options->model, "The .osim file")->required();
  cmd->add_option("--duration", options->duration, "Simulated time (s)")->required();
  cmd->add_option("--accuracy", options->accuracy, "Integrator accuracy (default 1e-6)");
  cmd->add_option("--integrator", options->integrator,
                  "rk45 (error-controlled, default) or euler (fixed step)");
  cmd->add_option("--step", options->step, "Fixed step for euler; largest step for rk45 (s)");
  cmd->add_option("--report-interval", options->report_interval,
                  "Time between output rows (s, default 0.01)");
  cmd->add_option("--initial-states", options->initial_states,
                  "Storage file whose first row gives the initial coordinates and speeds");
  cmd->add_option("--out", options->out, "Output folder")->required();
  cmd->add_flag("--quiet", options->quiet, "No progress bar or summary");
  cmd->callback([options]() { RunSimulate(*options); });
}

}  // namespace sinew::cli

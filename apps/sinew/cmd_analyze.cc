// `sinew analyze MODEL.osim --motion F.mot --out DIR [--coordinates a,b]
//  [--cylinder-refinement several-wraps|opensim-4.4|always]`: OpenSim
// MuscleAnalysis-style tables of every geometry path (muscles, path springs, ligaments) over a
// motion: Length.sto, LengtheningSpeed.sto and MomentArm_<coordinate>.sto; and, when the file
// is a states file holding muscles' activation and fiber_length, FiberLength.sto,
// TendonLength.sto, ActiveFiberForce.sto, PassiveFiberForce.sto and TendonForce.sto of those
// muscles (muscle_tables.h). The moment arms are OpenSim's (PathAnalysis::opensim_moment_arm:
// -dL/dq except where several wrap objects leave a tangent point stale, docs/paths.md).
#include <sinew/common/error.h>
#include <sinew/io/osim_reader.h>
#include <sinew/io/storage.h>
#include <sinew/io/storage_functions.h>
#include <sinew/io/storage_labels.h>
#include <sinew/kinematics/coordinate_couplers.h>
#include <sinew/kinematics/coordinate_motion.h>
#include <sinew/kinematics/kinematic_tree.h>
#include <sinew/paths/path_analysis.h>
#include <sinew/paths/path_set.h>

#include <filesystem>
#include <iostream>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "apps/sinew/commands.h"
#include "apps/sinew/muscle_tables.h"
#include "apps/sinew/notices.h"
#include "apps/sinew/option_checks.h"
#include "apps/sinew/output_files.h"
#include "apps/sinew/tables.h"

namespace sinew::cli {
namespace {

struct Options {
  std::string model;
  std::string motion;
  std::string out;
  std::vector<std::string> coordinates;
  std::string cylinder_refinement = "several-wraps";
};

// The coordinates to write moment arms about: those named by --coordinates, or every coordinate
// that can move on its own (not locked, not set by a coupler).
std::vector<int> ChooseCoordinates(const model::ModelSpec& spec,
                                   const kinematics::CoordinateCouplers& couplers,
                                   const std::vector<std::string>& names) {
  std::vector<int> out;
  if (names.empty()) {
    for (size_t c = 0; c < spec.coordinates.size(); ++c) {
      if (!spec.coordinates[c].locked && !couplers.Drives(static_cast<int>(c))) {
        out.push_back(static_cast<int>(c));
      }
    }
    return out;
  }
  for (const std::string& name : names) {
    const int c = spec.FindCoordinate(name);
    if (c == model::kNone) {
      throw Error("--coordinates: the model has no coordinate '" + name + "'");
    }
    out.push_back(c);
  }
  return out;
}

// The coordinate speeds of the motion: the first derivative of OpenSim's spline through each
// coordinate column (GCVSplineSet of degree 5, as its AnalyzeTool differentiates a motion), in
// radians. Empty when the table has too few rows for that spline.
std::vector<functions::FunctionPtr> FitSpeedSplines(io::Storage motion,
                                                    const model::ModelSpec& spec) {
  std::vector<std::string> rotational;
  for (const model::CoordinateSpec& c : spec.coordinates) {
    if (c.motion_type == model::MotionType::kRotational) rotational.push_back(c.name);
  }
  io::ConvertDegreesToRadians(motion, rotational);
  constexpr int kHalfOrder = 3;
  if (motion.NumRows() < 2 * kHalfOrder) return {};
  return io::FitColumnSplines(motion, kHalfOrder);
}

io::Storage MakeTable(const std::string& name, const paths::PathSet& paths) {
  io::Storage table;
  table.name = name;
  for (const paths::GeometryPath& path : paths.paths()) table.labels.push_back(path.name());
  return table;
}

void Run(const Options& options) {
  PrepareOutputFolder(options.out);
  model::ModelSpec spec = io::ReadOsim(options.model);
  UseStandIns(spec, options.model);
  const kinematics::KinematicTree tree(spec);
  const kinematics::CoordinateCouplers couplers(spec);
  const paths::PathSet paths(spec, CylinderRefinementOption(options.cylinder_refinement));
  if (paths.paths().empty()) {
    throw Error({options.model, 0}, "", "the model has no geometry path to analyze");
  }
  for (const Diagnostic& d : paths.ListOmissions(spec)) {
    std::cerr << "sinew: warning: " << d.Format() << "\n";
  }
  const std::vector<int> coordinates = ChooseCoordinates(spec, couplers, options.coordinates);

  const io::Storage motion = ReadTableFor(options.motion, spec);
  if (motion.NumRows() == 0) throw Error({options.motion, 0}, "", "the motion has no rows");
  std::vector<std::string> path_names;
  for (const paths::GeometryPath& path : paths.paths()) path_names.push_back(path.name());
  MuscleTables muscle_tables(spec, motion, path_names);
  const kinematics::MotionColumnMap map = MapMotionColumnsFor(
      motion, options.motion, spec, couplers, "they keep their default values and zero speed",
      muscle_tables.used_labels());
  const std::vector<functions::FunctionPtr> splines = FitSpeedSplines(motion, spec);
  if (splines.empty()) {
    std::cerr << "sinew: warning: " << options.motion << " has " << motion.NumRows()
              << " rows, fewer than the 6 a quintic spline needs: lengthening speeds are "
                 "written as NaN\n";
  }

  io::Storage lengths = MakeTable("Length", paths);
  io::Storage speeds = MakeTable("LengtheningSpeed", paths);
  std::vector<io::Storage> moment_arms;
  for (int c : coordinates)
    moment_arms.push_back(MakeTable("MomentArm_" + spec.coordinates[c].name, paths));

  const std::vector<double> no_speeds(paths.paths().size(),
                                      std::numeric_limits<double>::quiet_NaN());

  paths::PathAnalysis analysis(spec, tree, couplers, paths, coordinates);
  std::vector<double> q = tree.default_q();
  std::vector<double> u(q.size());
  const size_t num_columns = motion.labels.size();
  const size_t num_paths = paths.paths().size();
  std::vector<double> row(num_paths);
  for (int r = 0; r < motion.NumRows(); ++r) {
    const double t = motion.time[r];
    kinematics::ApplyMotionRow(
        spec, map, std::span<const double>(motion.values.data() + r * num_columns, num_columns),
        motion.in_degrees, q);
    std::fill(u.begin(), u.end(), 0.0);
    for (size_t k = 0; k < num_columns && !splines.empty(); ++k) {
      if (map.coordinate[k] != model::kNone)
        u[map.coordinate[k]] = splines[k]->CalcDerivative(t, 1);
    }
    couplers.Apply(q);
    couplers.ApplySpeeds(q, u);
    analysis.Calc(q, u);
    lengths.AppendRow(t, analysis.lengths());
    if (splines.empty()) {
      speeds.AppendRow(t, std::vector<double>(num_paths, std::numeric_limits<double>::quiet_NaN()));
    } else {
      speeds.AppendRow(t, analysis.lengthening_speeds());
    }
    for (size_t k = 0; k < coordinates.size(); ++k) {
      for (size_t p = 0; p < num_paths; ++p) row[p] = analysis.opensim_moment_arm(k, p);
      moment_arms[k].AppendRow(t, row);
    }
    if (!muscle_tables.empty()) {
      muscle_tables.AppendRow(motion, r, analysis.lengths(),
                              splines.empty() ? no_speeds : analysis.lengthening_speeds());
    }
  }

  const std::filesystem::path dir(options.out);
  io::WriteStorage(lengths, (dir / "Length.sto").string());
  io::WriteStorage(speeds, (dir / "LengtheningSpeed.sto").string());
  for (const io::Storage& table : moment_arms) {
    io::WriteStorage(table, (dir / (table.name + ".sto")).string());
  }
  if (!muscle_tables.empty()) muscle_tables.Write(options.out);
}

}  // namespace

void AddAnalyzeCommand(CLI::App& app) {
  auto options = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "analyze", "Muscle and other path lengths, lengthening speeds and moment arms over a motion");
  cmd->add_option("model", options->model, "OpenSim model (.osim)")->required();
  cmd->add_option("--motion", options->motion, "Coordinates over time (.mot/.sto)")->required();
  cmd->add_option("--out", options->out,
                  "Output directory (Length.sto, LengtheningSpeed.sto, MomentArm_<coordinate>.sto; "
                  "with muscle states: FiberLength, TendonLength, ActiveFiberForce, "
                  "PassiveFiberForce, TendonForce)")
      ->required();
  cmd->add_option("--coordinates", options->coordinates,
                  "Coordinates for the moment arms (default: every one not locked or coupled)")
      ->delimiter(',');
  AddCylinderRefinementOption(cmd, options->cylinder_refinement);
  cmd->callback([options] { Run(*options); });
}

}  // namespace sinew::cli

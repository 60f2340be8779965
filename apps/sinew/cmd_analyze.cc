// `sinew analyze MODEL.osim --motion F.mot --out DIR [--coordinates a,b]
//  [--cylinder-refinement several-wraps|opensim-4.4|always]`: OpenSim
// MuscleAnalysis-style tables of every geometry path (muscles, path springs, ligaments) over a
// motion: Length.sto, LengtheningSpeed.sto and MomentArm_<coordinate>.sto; and, when the file
// is a states file holding muscles' activation and fiber_length, FiberLength.sto,
// TendonLength.sto, ActiveFiberForce.sto, PassiveFiberForce.sto and TendonForce.sto of those
// muscles (opensim::MuscleAnalysis, which Python's Model.analyze uses too). The moment arms are
// OpenSim's (PathAnalysis::opensim_moment_arm: -dL/dq except where several wrap objects leave a
// tangent point stale, docs/paths.md).
#include <sinew/common/error.h>
#include <sinew/io/osim_reader.h>
#include <sinew/io/storage.h>
#include <sinew/kinematics/coordinate_couplers.h>
#include <sinew/opensim/muscle_analysis.h>

#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "apps/sinew/commands.h"
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

void Run(const Options& options) {
  PrepareOutputFolder(options.out);
  model::ModelSpec spec = io::ReadOsim(options.model);
  UseStandIns(spec, options.model);
  const kinematics::CoordinateCouplers couplers(spec);
  const io::Storage motion = ReadTableFor(options.motion, spec);
  Diagnostics notes;
  const opensim::MuscleAnalysis analysis(spec, options.model,
                                         CylinderRefinementOption(options.cylinder_refinement),
                                         motion, options.motion, &notes);
  for (const Diagnostic& d : analysis.paths().ListOmissions(spec)) {
    std::cerr << "sinew: warning: " << d.Format() << "\n";
  }
  const std::vector<int> coordinates = [&] {
    try {
      return opensim::ChooseMomentArmCoordinates(spec, couplers, options.coordinates);
    } catch (const Error& e) {
      throw Error(std::string("--coordinates: ") + e.what());
    }
  }();
  if (motion.NumRows() == 0) throw Error({options.motion, 0}, "", "the motion has no rows");
  MapMotionColumnsFor(motion, options.motion, spec, couplers,
                      "they keep their default values and zero speed",
                      analysis.muscle_state_labels());
  const opensim::MuscleAnalysisTables tables = analysis.Run(coordinates, &notes);
  for (const Diagnostic& d : notes) std::cerr << "sinew: warning: " << d.Format() << "\n";

  const std::filesystem::path dir(options.out);
  io::WriteStorage(tables.length, (dir / "Length.sto").string());
  io::WriteStorage(tables.lengthening_speed, (dir / "LengtheningSpeed.sto").string());
  for (const std::vector<io::Storage>* group : {&tables.moment_arms, &tables.muscles}) {
    for (const io::Storage& table : *group) {
      io::WriteStorage(table, (dir / (table.name + ".sto")).string());
    }
  }
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

// `sinew kinematics MODEL.osim [--motion FILE] --out DIR`: body mass-centre positions and
// orientations (OpenSim BodyKinematics layout) and marker locations, at the default pose or for
// every row of a motion file.
#include <sinew/common/error.h>
#include <sinew/io/osim_reader.h>
#include <sinew/io/storage.h>
#include <sinew/kinematics/body_kinematics.h>
#include <sinew/kinematics/coordinate_couplers.h>
#include <sinew/kinematics/coordinate_motion.h>
#include <sinew/kinematics/forward_kinematics.h>
#include <sinew/kinematics/kinematic_tree.h>

#include <filesystem>
#include <iostream>
#include <span>
#include <string>
#include <vector>

#include "apps/sinew/commands.h"
#include "apps/sinew/notices.h"
#include "apps/sinew/output_files.h"
#include "apps/sinew/tables.h"

namespace sinew::cli {
namespace {

struct Options {
  std::string model;
  std::string motion;
  std::string out;
};

void Run(const Options& options) {
  PrepareOutputFolder(options.out);
  model::ModelSpec spec = io::ReadOsim(options.model);
  UseStandIns(spec, options.model);
  const kinematics::KinematicTree tree(spec);
  for (int j : tree.loop_joints()) {
    std::cerr << "sinew: note: joint '" << spec.joints[j].name
              << "' closes a kinematic loop; it is not enforced by forward kinematics\n";
  }
  std::vector<double> q = tree.default_q();
  std::vector<Transform> X_GB(tree.num_bodies());
  // Coupler-driven coordinates (Rajagopal's patellae) follow their drivers.
  const kinematics::CoordinateCouplers couplers(spec);

  io::Storage motion;
  kinematics::MotionColumnMap map;
  if (!options.motion.empty()) {
    motion = ReadTableFor(options.motion, spec);
    map = MapMotionColumnsFor(motion, options.motion, spec, couplers,
                              "they keep their default values");
  } else {
    motion.time = {0.0};  // one row at the default pose
  }

  io::Storage bodies, markers;
  bodies.name = "Positions";
  bodies.labels = kinematics::BodyKinematicsLabels(spec);
  // OpenSim writes these angles in degrees under inDegrees=no; we write what they are.
  bodies.in_degrees = true;
  markers.name = "Model Marker Locations";
  markers.labels = kinematics::MarkerLocationLabels(spec);
  const size_t num_columns = motion.labels.size();
  for (int r = 0; r < motion.NumRows(); ++r) {
    if (num_columns > 0) {
      kinematics::ApplyMotionRow(
          spec, map, std::span<const double>(motion.values.data() + r * num_columns, num_columns),
          motion.in_degrees, q);
    }
    couplers.Apply(q);
    kinematics::CalcBodyPoses(tree, q, X_GB);
    bodies.AppendRow(motion.time[r], kinematics::CalcBodyKinematicsRow(spec, X_GB));
    markers.AppendRow(motion.time[r], kinematics::CalcMarkerLocationRow(spec, X_GB));
  }

  const std::filesystem::path dir(options.out);
  io::WriteStorage(bodies, (dir / "bodies.sto").string());
  if (!spec.markers.empty()) io::WriteStorage(markers, (dir / "markers.sto").string());
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

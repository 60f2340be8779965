// `sinew export MODEL.osim [--motion FILE | --states FILE] [--contacts FILE]
//  --vis primitives|mesh [--no-paths] [--collision]
//  [--verbose] --out FILE.glb|FILE.html`: the model (and its motion) for a glTF viewer or a
//  browser.
#include <sinew/io/osim_reader.h>
#include <sinew/io/storage.h>
#include <sinew/viz/export_animation.h>
#include <sinew/viz/motion_poses.h>

#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "apps/sinew/collision_drawing.h"
#include "apps/sinew/commands.h"
#include "apps/sinew/notices.h"
#include "apps/sinew/option_checks.h"
#include "apps/sinew/output_files.h"
#include "apps/sinew/tables.h"

namespace sinew::cli {
namespace {

struct ExportArgs {
  std::string model;
  std::string motion;
  std::string states;
  std::string contacts;
  std::string vis = "mesh";
  std::string out;
  std::vector<std::string> geometry_dirs;
  double fps = 0;
  bool no_paths = false;
  bool collision = false;
  bool verbose = false;
};

void RunExport(const ExportArgs& args) {
  viz::ExportFormatOf(args.out);
  PrepareOutputFile(args.out);
  model::ModelSpec spec = io::ReadOsim(args.model);
  UseStandIns(spec, args.model);
  viz::ExportOptions options;
  options.visual.mode = viz::ParseVisType(args.vis);
  options.visual.geometry_dirs = args.geometry_dirs;
  options.max_fps = args.fps;
  options.paths = !args.no_paths;
  if (args.collision) options.collision_parts = ModelCollisionParts(spec, args.geometry_dirs);
  viz::BodyMotion motion;
  io::Storage table, contacts;
  const std::string& table_file = args.motion.empty() ? args.states : args.motion;
  if (!args.contacts.empty()) {
    if (table_file.empty()) throw Error("--contacts needs --motion or --states");
    contacts = io::ReadStorage(args.contacts);
    options.contacts = &contacts;
  }
  if (table_file.empty()) {
    motion = viz::DefaultPoseMotion(spec);
  } else {
    Diagnostics notes;
    table = ReadTableFor(table_file, spec);
    motion = viz::MotionFromTable(spec, table, &notes);
    PrintTableNotes(notes);
    options.activations = &table;  // a states file's activations shade the muscles
  }
  PrintSceneWarnings(viz::ExportAnimation(spec, motion, args.out, options), args.verbose);
  std::cout << "wrote " << args.out << " (" << spec.bodies.size() << " bodies, "
            << motion.times.size() << " frames)\n";
}

}  // namespace

void AddExportCommand(CLI::App& app) {
  auto args = std::make_shared<ExportArgs>();
  CLI::App* cmd = app.add_subcommand(
      "export",
      "Export a model and its motion as binary glTF (.glb) or a self-contained HTML viewer");
  cmd->add_option("model", args->model, "OpenSim model file (.osim)")->required();
  auto* motion = cmd->add_option("--motion", args->motion, "Coordinates over time (.mot/.sto)");
  auto* states = cmd->add_option("--states", args->states, "States over time (.sto)");
  motion->excludes(states);
  cmd->add_option("--contacts", args->contacts,
                  "Contact forces over time (a contacts.sto of `sinew simulate`), drawn as arrows");
  cmd->add_option("--vis", args->vis, "Visualization: primitives, mesh or none")
      ->check(CLI::IsMember({"primitives", "mesh", "none"}));
  cmd->add_option("--geometry-dir", args->geometry_dirs,
                  "Extra folder to search for mesh files (repeatable; also $SINEW_GEOMETRY_PATH)");
  cmd->add_option("--fps", args->fps, "Keep at most this many frames per second (default: all)")
      ->check(FiniteNumber(0.0));
  cmd->add_flag("--collision", args->collision,
                "Also draw the collision shapes (the seed's cylinders, the contact geometry that "
                "collides), as simulate --collision --export does");
  cmd->add_flag("--no-paths", args->no_paths,
                "Leave out the muscle, spring and ligament paths (drawn as red lines)");
  cmd->add_flag(
      "--verbose", args->verbose,
      "List every missing mesh file, not just how many, and where each mesh was read from");
  cmd->add_option("--out,-o", args->out, "Output file: .glb or .html (folders are created)")
      ->required();
  cmd->callback([args] { RunExport(*args); });
}

}  // namespace sinew::cli

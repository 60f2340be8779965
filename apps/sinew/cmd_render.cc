// `sinew render MODEL.osim [--motion FILE | --states FILE] [--time T] [--contacts FILE]
//  [--no-paths] [--collision] [--verbose] --out FILE.png`: a still picture made by the built-in
//  software renderer (no display or GPU needed), with the contact forces of a contacts.sto at
//  the shown time as green arrows, as the viewer draws them.
#include <sinew/io/osim_reader.h>
#include <sinew/io/storage.h>
#include <sinew/viz/contact_arrows.h>
#include <sinew/viz/gltf_writer.h>
#include <sinew/viz/motion_poses.h>
#include <sinew/viz/path_lines.h>
#include <sinew/viz/rasterizer.h>
#include <sinew/viz/view_hints.h>

#include <algorithm>
#include <cmath>
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

struct RenderArgs {
  std::string model;
  std::string motion;
  std::string states;
  std::string contacts;
  double time = 0;
  bool has_time = false;
  std::string vis = "mesh";
  std::string view = "iso";
  int width = 800;
  int height = 800;
  std::string out;
  std::vector<std::string> geometry_dirs;
  bool no_floor = false;
  bool no_paths = false;
  bool collision = false;
  bool verbose = false;
};

void RunRender(const RenderArgs& args) {
  RequireExtension(args.out, ".png", "PNG");
  viz::CheckRenderSize(args.width, args.height);
  PrepareOutputFile(args.out);
  model::ModelSpec spec = io::ReadOsim(args.model);
  UseStandIns(spec, args.model);
  viz::VisualOptions visual;
  visual.mode = viz::ParseVisType(args.vis);
  visual.geometry_dirs = args.geometry_dirs;
  viz::BodyMotion frame;
  io::Storage table;
  const std::string& table_file = args.motion.empty() ? args.states : args.motion;
  if (table_file.empty()) {
    if (args.has_time) throw Error("--time needs --states or --motion");
    if (!args.contacts.empty()) throw Error("--contacts needs --motion or --states");
    frame = viz::DefaultPoseMotion(spec);
  } else {
    table = ReadTableFor(table_file, spec);
    const double t = args.has_time || table.time.empty() ? args.time : table.time.front();
    Diagnostics notes;
    frame = viz::MotionAtTime(spec, table, t, &notes);
    PrintTableNotes(notes);
  }
  const std::vector<Transform>& X_GB = frame.X_GB[0];
  viz::VisualScene scene = viz::BuildVisualScene(spec, visual);
  if (args.collision) viz::AddCollisionParts(ModelCollisionParts(spec, args.geometry_dirs), scene);
  std::vector<std::vector<Vec3>> lines;
  std::vector<Vec3> line_colors;
  if (!args.no_paths) {
    viz::PathLines paths = viz::CalcPathLines(spec, frame, &scene.warnings);
    // A states file's activations shade the muscles.
    if (!paths.vertices.empty()) {
      viz::ShadeByActivation(table, frame.times, paths);
      for (size_t i = 0; i < paths.names.size(); ++i) {
        line_colors.push_back(viz::PathColor(
            paths, paths.activation.empty() ? std::nan("") : paths.activation[0][i]));
      }
      lines = std::move(paths.vertices[0]);
    }
  }
  viz::RenderOptions options;
  options.width = args.width;
  options.height = args.height;
  options.floor = !args.no_floor;
  options.floor_plane = viz::ViewFloor(spec, scene, frame);
  if (!args.contacts.empty()) {
    options.overlay = viz::ContactArrowPartsAt(spec, io::ReadStorage(args.contacts), table, frame,
                                               scene, *options.floor_plane, &scene.warnings);
  }
  PrintSceneWarnings(scene, args.verbose);
  options.view_direction = viz::ParseViewDirection(args.view);
  viz::WriteFileBytes(args.out,
                      viz::EncodePng(viz::RenderFramed(scene, X_GB, options, lines, line_colors)));
  std::cout << "wrote " << args.out << " (" << args.width << "x" << args.height << ")\n";
}

}  // namespace

void AddRenderCommand(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand("render", "Render a still PNG image of a model (no display)");
  cmd->add_option("model", args->model, "OpenSim model file (.osim)")->required();
  auto* motion = cmd->add_option("--motion", args->motion, "Coordinates over time (.mot/.sto)");
  auto* states = cmd->add_option("--states", args->states, "States over time (.sto)");
  motion->excludes(states);
  cmd->add_option("--contacts", args->contacts,
                  "Contact forces over time (a contacts.sto of `sinew simulate`), drawn at the "
                  "shown time as green arrows, as in the viewer");
  cmd->add_option_function<double>(
         "--time", [args](double t) { args->time = t, args->has_time = true; },
         "Time (s) in the table to show (default: its first row)")
      ->check(FiniteNumber());
  cmd->add_option("--vis", args->vis, "Visualization: primitives, mesh or none")
      ->check(CLI::IsMember({"primitives", "mesh", "none"}));
  cmd->add_option("--view", args->view, "Camera: iso, front, back, right, left or top")
      ->check(CLI::IsMember({"iso", "front", "back", "right", "left", "top"}));
  cmd->add_option("--width", args->width,
                  "Image width (pixels; at most 8192, and about 9 million pixels in all)")
      ->check(CLI::Range(1, 8192));
  cmd->add_option("--height", args->height, "Image height (pixels)")->check(CLI::Range(1, 8192));
  cmd->add_option("--geometry-dir", args->geometry_dirs,
                  "Extra folder to search for mesh files (repeatable; also $SINEW_GEOMETRY_PATH)");
  cmd->add_flag("--no-floor", args->no_floor, "Leave out the floor and the model's shadow");
  cmd->add_flag("--collision", args->collision,
                "Also draw the collision shapes (the seed's cylinders, the contact geometry that "
                "collides), as simulate --collision --export does");
  cmd->add_flag("--no-paths", args->no_paths,
                "Leave out the muscle, spring and ligament paths (drawn as red lines)");
  cmd->add_flag(
      "--verbose", args->verbose,
      "List every missing mesh file, not just how many, and where each mesh was read from");
  cmd->add_option("--out,-o", args->out, "Output PNG file (.png; folders are created)")->required();
  cmd->callback([args] { RunRender(*args); });
}

}  // namespace sinew::cli

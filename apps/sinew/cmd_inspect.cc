// `sinew inspect MODEL.osim [--json]`: what a model file says and what the OpenSim parser
// builds from it (its Report), as text or one JSON object.
#include <sinew/io/osim_reader.h>
#include <sinew/opensim/parser.h>
#include <sinew/opensim/support.h>
#include <sinew/paths/path_set.h>

#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "apps/sinew/commands.h"

namespace sinew::cli {
namespace {

// The name of a body for display: "ground" for ground.
const std::string& BodyName(const model::ModelSpec& spec, int body) {
  return spec.bodies[body].name;
}

const char* MotionName(model::MotionType type) {
  switch (type) {
    case model::MotionType::kRotational:
      return "rotational";
    case model::MotionType::kTranslational:
      return "translational";
    case model::MotionType::kCoupled:
      return "coupled";
  }
  return "?";
}

// One force's path as inspect shows it: a GeometryPath's points and wraps, or a
// FunctionBasedPath's coordinates and functions.
struct PathSummary {
  std::string name;
  int points = 0, conditional = 0, moving = 0;
  std::vector<std::string> wrap_objects;
  std::string type = "GeometryPath";
  std::vector<std::string> coordinates;  // FunctionBasedPath
  std::string functions;                 // FunctionBasedPath: which functions it has
};

PathSummary SummarizeFunctionPath(const model::ModelSpec& spec, const model::ForceSpec& f) {
  const model::FunctionBasedPathSpec& path = *f.function_based_path;
  PathSummary summary{f.name, 0, 0, 0, {}, "FunctionBasedPath", {}, {}};
  for (int c : path.coordinates) summary.coordinates.push_back(spec.coordinates[c].name);
  summary.functions = "length " + path.length_function->TypeName();
  if (!path.moment_arm_functions.empty()) summary.functions += ", moment arm functions";
  if (path.lengthening_speed_function) summary.functions += ", lengthening speed function";
  return summary;
}

std::vector<PathSummary> SummarizePaths(const model::ModelSpec& spec) {
  std::vector<PathSummary> out;
  for (const model::ForceSpec& f : spec.forces) {
    if (f.function_based_path && !f.geometry_path) out.push_back(SummarizeFunctionPath(spec, f));
    if (!f.geometry_path) continue;
    PathSummary path{
        f.name, static_cast<int>(f.geometry_path->points.size()), 0, 0, {}, "GeometryPath", {}, {}};
    for (const model::PathPointSpec& point : f.geometry_path->points) {
      path.conditional += point.type == "ConditionalPathPoint";
      path.moving += point.type == "MovingPathPoint";
    }
    for (const model::PathWrapSpec& wrap : f.geometry_path->wraps) {
      path.wrap_objects.push_back(wrap.wrap_object);
    }
    out.push_back(std::move(path));
  }
  return out;
}

// What `sinew analyze` leaves out of the model's paths, or why it cannot compute them.
std::vector<std::string> ListPathOmissions(const model::ModelSpec& spec) {
  std::vector<std::string> out;
  try {
    for (const Diagnostic& d : paths::PathSet(spec).ListOmissions(spec)) out.push_back(d.Format());
  } catch (const Error& e) {
    out.push_back(e.what());
  }
  return out;
}

nlohmann::json ToJson(const model::ModelSpec& spec) {
  using nlohmann::json;
  json out;
  out["name"] = spec.name;
  out["file"] = spec.file;
  out["version"] = spec.version;
  out["gravity"] = {spec.gravity.x(), spec.gravity.y(), spec.gravity.z()};
  json bodies = json::array();
  for (size_t i = 1; i < spec.bodies.size(); ++i) {
    const model::BodySpec& b = spec.bodies[i];
    bodies.push_back({{"name", b.name},
                      {"mass", b.mass},
                      {"mass_center", {b.mass_center.x(), b.mass_center.y(), b.mass_center.z()}},
                      {"geometry", b.geometry.size()},
                      {"wrap_objects", b.wrap_objects.size()}});
  }
  out["bodies"] = bodies;
  json joints = json::array();
  for (const model::JointSpec& j : spec.joints) {
    json coordinates = json::array();
    for (int c : j.coordinates) coordinates.push_back(spec.coordinates[c].name);
    joints.push_back({{"name", j.name},
                      {"type", j.type},
                      {"parent", BodyName(spec, j.parent_body)},
                      {"child", BodyName(spec, j.child_body)},
                      {"parent_frame", j.parent_frame},
                      {"child_frame", j.child_frame},
                      {"reverse", j.reverse},
                      {"coordinates", coordinates}});
  }
  out["joints"] = joints;
  json coordinates = json::array();
  for (const model::CoordinateSpec& c : spec.coordinates) {
    coordinates.push_back({{"name", c.name},
                           {"joint", c.joint >= 0 ? spec.joints[c.joint].name : ""},
                           {"motion_type", MotionName(c.motion_type)},
                           {"default_value", c.default_value},
                           {"default_speed_value", c.default_speed_value},
                           {"range", {c.range_min, c.range_max}},
                           {"clamped", c.clamped},
                           {"locked", c.locked},
                           {"prescribed", c.prescribed}});
  }
  out["coordinates"] = coordinates;
  json forces = json::array();
  for (const model::ForceSpec& f : spec.forces) {
    json force = {{"name", f.name}, {"type", f.type}, {"applies_force", f.applies_force}};
    if (f.geometry_path) force["path_points"] = f.geometry_path->points.size();
    forces.push_back(force);
  }
  out["forces"] = forces;
  json paths = json::array();
  for (const PathSummary& p : SummarizePaths(spec)) {
    if (p.type == "FunctionBasedPath") {
      paths.push_back({{"name", p.name},
                       {"type", p.type},
                       {"coordinates", p.coordinates},
                       {"functions", p.functions}});
      continue;
    }
    paths.push_back({{"name", p.name},
                     {"type", p.type},
                     {"points", p.points},
                     {"conditional_points", p.conditional},
                     {"moving_points", p.moving},
                     {"wrap_objects", p.wrap_objects}});
  }
  out["paths"] = paths;
  out["paths_not_computed"] = ListPathOmissions(spec);
  json constraints = json::array();
  for (const model::ConstraintSpec& c : spec.constraints) {
    constraints.push_back({{"name", c.name}, {"type", c.type}, {"enabled", c.enabled}});
  }
  out["constraints"] = constraints;
  json markers = json::array();
  for (const model::MarkerSpec& m : spec.markers) {
    markers.push_back({{"name", m.name}, {"body", BodyName(spec, m.body)}});
  }
  out["markers"] = markers;
  json contacts = json::array();
  for (const model::ContactGeometrySpec& c : spec.contact_geometry) {
    contacts.push_back({{"name", c.name}, {"type", c.type}, {"body", BodyName(spec, c.body)}});
  }
  out["contact_geometry"] = contacts;
  json controllers = json::array();
  for (const model::ControllerSpec& c : spec.controllers) {
    controllers.push_back({{"name", c.name}, {"type", c.type}});
  }
  out["controllers"] = controllers;
  json warnings = json::array();
  for (const Diagnostic& d : spec.warnings) warnings.push_back(d.Format());
  out["warnings"] = warnings;
  out["not_simulated"] = opensim::ListNotSimulated(spec);
  return out;
}

void PrintText(const model::ModelSpec& spec, std::ostream& os) {
  os << "model: " << spec.name << "\nfile: " << spec.file << "\nformat version: " << spec.version
     << "\ngravity: " << spec.gravity.x() << " " << spec.gravity.y() << " " << spec.gravity.z()
     << "\ncounts: " << spec.bodies.size() - 1 << " bodies, " << spec.joints.size() << " joints, "
     << spec.coordinates.size() << " coordinates, " << spec.forces.size() << " forces, "
     << spec.constraints.size() << " constraints, " << spec.markers.size() << " markers, "
     << spec.contact_geometry.size() << " contact geometry, " << spec.controllers.size()
     << " controllers\n";
  os << "\nbodies:\n";
  for (size_t i = 1; i < spec.bodies.size(); ++i) {
    os << "  " << spec.bodies[i].name << "  mass " << spec.bodies[i].mass << " kg\n";
  }
  os << "\njoints:\n";
  for (const model::JointSpec& j : spec.joints) {
    os << "  " << j.name << "  " << j.type << "  " << BodyName(spec, j.parent_body) << " -> "
       << BodyName(spec, j.child_body);
    if (!j.coordinates.empty()) {
      os << "  [";
      for (size_t k = 0; k < j.coordinates.size(); ++k) {
        os << (k ? ", " : "") << spec.coordinates[j.coordinates[k]].name;
      }
      os << "]";
    }
    os << "\n";
  }
  std::map<std::string, int> by_type;
  for (const model::ForceSpec& f : spec.forces) ++by_type[f.type];
  os << "\nforces by type:\n";
  for (const auto& [type, count] : by_type) os << "  " << type << ": " << count << "\n";
  const std::vector<PathSummary> paths = SummarizePaths(spec);
  os << "\npaths (" << paths.size() << "):\n";
  for (const PathSummary& p : paths) {
    if (p.type == "FunctionBasedPath") {
      os << "  " << p.name << "  FunctionBasedPath of";
      for (size_t k = 0; k < p.coordinates.size(); ++k) {
        os << (k ? ", " : " ") << p.coordinates[k];
      }
      os << " (" << p.functions << "; no points: not drawn)\n";
      continue;
    }
    os << "  " << p.name << "  " << p.points << " points (" << p.conditional << " conditional, "
       << p.moving << " moving), " << p.wrap_objects.size() << " wraps";
    for (size_t k = 0; k < p.wrap_objects.size(); ++k) {
      os << (k ? ", " : ": ") << p.wrap_objects[k];
    }
    os << "\n";
  }
  const std::vector<std::string> omissions = ListPathOmissions(spec);
  os << "\npath parts not computed (" << omissions.size() << "):\n";
  for (const std::string& line : omissions) os << "  " << line << "\n";
  os << "\nconstraints:\n";
  for (const model::ConstraintSpec& c : spec.constraints)
    os << "  " << c.name << "  " << c.type << "\n";
  os << "\nmarkers:\n";
  for (const model::MarkerSpec& m : spec.markers) {
    os << "  " << m.name << "  on " << BodyName(spec, m.body) << "\n";
  }
  os << "\nwarnings (" << spec.warnings.size() << "):\n";
  for (const Diagnostic& d : spec.warnings) os << "  " << d.Format() << "\n";
  const std::vector<std::string> not_simulated = opensim::ListNotSimulated(spec);
  os << "\nnot simulated (" << not_simulated.size() << "):\n";
  for (const std::string& line : not_simulated) os << "  " << line << "\n";
}

// What the parser builds from `spec`: its Report, or why the model cannot be simulated.
struct BuildOutcome {
  opensim::OpenSimParser parser;
  std::string error;  // empty when the build succeeded
};

std::unique_ptr<BuildOutcome> BuildForReport(const model::ModelSpec& spec) {
  auto outcome = std::make_unique<BuildOutcome>();
  try {
    engine::System system;
    outcome->parser.ParseSpec(system, spec);
    system.Finalize();
  } catch (const Error& e) {
    outcome->error = e.what();
  }
  return outcome;
}

nlohmann::json ReportToJson(const BuildOutcome& outcome) {
  using nlohmann::json;
  json out;
  out["simulatable"] = outcome.error.empty();
  if (!outcome.error.empty()) {
    out["error"] = outcome.error;
    return out;
  }
  const opensim::Report& report = outcome.parser.GetReport();
  json joints = json::array();
  for (const auto& [key, info] : report.joints()) {
    joints.push_back({{"name", key},
                      {"type", info.type},
                      {"engine_joint", opensim::JointFormName(info.form)},
                      {"standin", info.standin}});
  }
  out["joints"] = joints;
  json forces = json::array();
  for (const auto& [key, info] : report.forces()) {
    json force = {{"name", key}, {"type", info.type}, {"simulated", info.load != nullptr}};
    if (info.actuator) force["excitation"] = info.excitation_source;
    forces.push_back(force);
  }
  out["forces"] = forces;
  json warnings = json::array();
  for (const Diagnostic& d : report.warnings()) warnings.push_back(d.Format());
  out["warnings"] = warnings;
  return out;
}

void PrintReport(const BuildOutcome& outcome, std::ostream& os) {
  os << "\nbuilt by the parser:\n";
  if (!outcome.error.empty()) {
    os << "  cannot be simulated: " << outcome.error << "\n";
    return;
  }
  outcome.parser.GetReport().Print(os);
}

}  // namespace

void AddInspectCommand(CLI::App& app) {
  struct Options {
    std::string model;
    bool json = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand("inspect", "Summarize what an .osim model file says");
  cmd->add_option("model", options->model, "The .osim file")->required();
  cmd->add_flag("--json", options->json, "Print one JSON object instead of text");
  cmd->callback([options]() {
    const model::ModelSpec spec = io::ReadOsim(options->model);
    const std::unique_ptr<BuildOutcome> build = BuildForReport(spec);
    if (options->json) {
      nlohmann::json out = ToJson(spec);
      out["build"] = ReportToJson(*build);
      // Names are bytes from the file: invalid UTF-8 is shown as U+FFFD, not an internal error.
      std::cout << out.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    } else {
      PrintText(spec, std::cout);
      PrintReport(*build, std::cout);
    }
  });
}

}  // namespace sinew::cli

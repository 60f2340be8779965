#include <sinew/forces/external_force.h>
#include <sinew/io/external_loads.h>
#include <sinew/io/storage.h>
#include <sinew/opensim/internal/external_force_builder.h>

#include <filesystem>
#include <optional>

namespace sinew::opensim::internal {
namespace {

// The line of property `tag` of the force, or the force's own line.
int LineOf(const ForceBuildInput& in, const char* tag) {
  const model::Element* child = in.force.element.Child(tag);
  return child ? child->line : in.force.element.line;
}

// The engine body property `tag` names ("ground", a body name or a path to one). An unknown
// name is an error for the applied body or when it is a path (an offset frame Sinew does not
// resolve), and otherwise ground with a note for the others (OpenSim).
int FindBody(const ForceBuildInput& in, const char* tag, bool required) {
  const std::string name = in.values.String(tag, required ? "" : "ground");
  const int b = in.spec.FindBody(LastPathSegment(name));
  if (b != model::kNone) return in.body_map[b];
  // A path that names no body may name an offset frame, which OpenSim would use: refuse it
  // rather than fall back to ground.
  if (required || name.find('/') != std::string::npos) {
    in.values.Fail(std::string(tag) + " '" + name + "' is not a body of the model",
                   LineOf(in, tag));
  }
  if (in.notes) {
    const std::string& file = in.external_loads ? in.external_loads->file : in.spec.file;
    in.notes->push_back({SourceLocation{file, LineOf(in, tag)}, in.force.path,
                         std::string(tag) + " '" + name +
                             "' is not a body of the model: ground is used, as OpenSim does"});
  }
  return 0;
}

// The data an ExternalForce of a model's ForceSet reads: the storage `data_source_name` names
// beside the model.
io::Storage ReadForceSetData(const ForceBuildInput& in, std::string& data_file) {
  const std::string source = in.values.String("data_source_name");
  if (!io::IsIdentifierSet(source)) {
    in.values.Fail(
        "an ExternalForce in the ForceSet has no data (OpenSim gives it data only through an "
        "ExternalLoads file: pass that file instead, e.g. `sinew simulate --external-loads`)");
  }
  std::filesystem::path path(source);
  if (path.is_relative()) path = std::filesystem::path(in.spec.file).parent_path() / path;
  data_file = path.lexically_normal().string();
  try {
    return io::ReadStorage(data_file);
  } catch (const Error& error) {
    in.values.Fail("data_source_name: cannot read '" + data_file + "': " + error.what(),
                   LineOf(in, "data_source_name"));
  }
}

// The three functions of the part `tag` names (force_identifier, ...), or none when the
// identifier is unset.
std::array<functions::FunctionPtr, 3> FitPart(const ForceBuildInput& in, const io::Storage& data,
                                              const std::string& data_file, const char* tag) {
  const std::string identifier = in.values.String(tag);
  if (!io::IsIdentifierSet(identifier)) return {};
  const std::vector<int> columns = io::FindIdentifierColumns(data, identifier);
  if (columns.size() != 3) {
    std::string found;
    for (int c : columns) found += (found.empty() ? "" : ", ") + data.labels[c];
    in.values.Fail(std::string(tag) + " '" + identifier + "' names " +
                       std::to_string(columns.size()) + " columns of " + data_file +
                       (found.empty() ? "" : " (" + found + ")") +
                       "; it needs exactly 3 whose labels begin with it (X, Y, Z in order)",
                   LineOf(in, tag));
  }
  std::array<functions::FunctionPtr, 3> part;
  for (int i = 0; i < 3; ++i) {
    try {
      part[i] = io::FitExternalForceColumn(data, columns[i]);
    } catch (const Error& error) {
      in.values.Fail(data_file + ", column '" + data.labels[columns[i]] + "': " + error.message(),
                     LineOf(in, tag));
    }
  }
  return part;
}

}  // namespace

std::shared_ptr<engine::ForceElement> BuildExternalForce(const ForceBuildInput& in) {
  std::string data_file;
  std::optional<io::Storage> own_data;
  if (in.external_loads) {
    data_file = in.external_loads->data_file;
  } else {
    own_data = ReadForceSetData(in, data_file);
  }
  const io::Storage& data = own_data ? *own_data : in.external_loads->data;

  forces::ExternalForceBodies bodies;
  bodies.applied_to = FindBody(in, "applied_to_body", true);
  bodies.force_in = FindBody(in, "force_expressed_in_body", false);
  forces::ExternalForceFunctions functions;
  functions.force = FitPart(in, data, data_file, "force_identifier");
  functions.torque = FitPart(in, data, data_file, "torque_identifier");
  if (!functions.force[0] && !functions.torque[0]) {
    in.values.Fail("an ExternalForce needs a force_identifier or a torque_identifier");
  }
  // A point without a force means nothing (OpenSim refuses it): only read with a force.
  if (functions.force[0]) {
    functions.point = FitPart(in, data, data_file, "point_identifier");
    if (functions.point[0]) bodies.point_in = FindBody(in, "point_expressed_in_body", false);
  } else if (io::IsIdentifierSet(in.values.String("point_identifier"))) {
    in.values.Fail("point_identifier is given but no force_identifier",
                   LineOf(in, "point_identifier"));
  }
  return std::make_shared<forces::ExternalForce>(in.force.name, in.values.String("applied_to_body"),
                                                 bodies, std::move(functions));
}

}  // namespace sinew::opensim::internal

#include <sinew/common/error.h>
#include <sinew/functions/constant.h>
#include <sinew/functions/gcv_spline.h>
#include <sinew/functions/piecewise_linear_function.h>
#include <sinew/io/external_loads.h>
#include <sinew/io/internal/osim_context.h>
#include <sinew/io/internal/xml_document.h>

#include <filesystem>
#include <memory>

namespace sinew::io {
namespace {

using internal::XmlDocument;

// The ExternalLoads element of a document (the root itself, or under <OpenSimDocument>).
pugi::xml_node FindExternalLoads(const XmlDocument& doc) {
  pugi::xml_node root = doc.root();
  if (std::string_view(root.name()) == "OpenSimDocument") root = root.child("ExternalLoads");
  if (!root || std::string_view(root.name()) != "ExternalLoads") {
    doc.Fail(doc.root(), "",
             "not an ExternalLoads file (root element <" + std::string(doc.root().name()) + ">)");
  }
  return root;
}

// `datafile` as written when absolute, else relative to the folder of the xml file.
std::string ResolveDataFile(const std::string& xml_file, const std::string& datafile) {
  const std::filesystem::path path(datafile);
  if (path.is_absolute()) return datafile;
  return (std::filesystem::path(xml_file).parent_path() / path).lexically_normal().string();
}

}  // namespace

bool IsIdentifierSet(std::string_view identifier) {
  return identifier.find_first_not_of(" \t") != std::string_view::npos &&
         identifier != "Unassigned";
}

ExternalLoads ReadExternalLoads(const std::string& file) {
  const XmlDocument doc = XmlDocument::Load(file);
  const pugi::xml_node node = FindExternalLoads(doc);
  ExternalLoads loads;
  loads.file = file;
  loads.name = internal::NameOf(node);
  const std::string owner = "/" + (loads.name.empty() ? std::string("externalloads") : loads.name);

  for (const pugi::xml_node& child : internal::ObjectsOf(node)) {
    const std::string name = internal::NameOf(child);
    const std::string path = owner + "/" + name;
    const std::string_view type = child.name();
    if (type == "PrescribedForce") {
      doc.Fail(child, path,
               "an ExternalLoads file of the pre-2.3.1 form (PrescribedForce elements naming "
               "columns) is not supported; write ExternalForce elements with identifiers");
    }
    if (type != "ExternalForce") {
      doc.Fail(child, path, "<" + std::string(type) + "> is not an ExternalForce");
    }
    model::ForceSpec force;
    force.name = name;
    force.path = path;
    force.type = "ExternalForce";
    force.applies_force = internal::ReadEnabledFlag(doc, child, "appliesForce", path, true);
    force.element = internal::ToElement(doc, child);
    force.where = doc.Where(child);
    loads.forces.push_back(std::move(force));
  }

  // 3.x files carry options OpenSim 4 no longer applies (it warns for a kinematics file).
  const std::string kinematics = internal::TextOf(node, "external_loads_model_kinematics_file");
  if (!kinematics.empty() && kinematics != "Unassigned") {
    loads.notes.push_back({doc.Where(node.child("external_loads_model_kinematics_file")), owner,
                           "external_loads_model_kinematics_file '" + kinematics +
                               "' is ignored, as OpenSim 4 ignores it (points are used as "
                               "written)"});
  }

  const pugi::xml_node datafile = node.child("datafile");
  const std::string data_name = datafile ? internal::TextOf(node, "datafile") : "";
  if (data_name.empty() || data_name == "Unassigned") {
    doc.Fail(datafile ? datafile : node, owner,
             "no <datafile>: the ExternalForces have no data to read");
  }
  loads.data_file = ResolveDataFile(file, data_name);
  try {
    loads.data = ReadStorage(loads.data_file);
  } catch (const Error& error) {
    throw Error(doc.Where(datafile), owner + "/datafile",
                "cannot read '" + loads.data_file + "': " + error.what());
  }
  return loads;
}

std::vector<int> FindIdentifierColumns(const Storage& data, std::string_view identifier) {
  std::vector<int> columns;
  if (identifier.empty()) return columns;
  for (int c = 0; c < data.NumColumns(); ++c) {
    if (std::string_view(data.labels[c]).starts_with(identifier)) columns.push_back(c);
  }
  return columns;
}

functions::FunctionPtr FitExternalForceColumn(const Storage& data, int column) {
  std::vector<double> values = data.Column(column);
  switch (data.NumRows()) {
    case 0:
      throw Error("the data file has no rows");
    case 1:
      return std::make_shared<functions::Constant>(values[0]);
    case 2:
    case 3:
      return std::make_shared<functions::PiecewiseLinearFunction>(data.time, std::move(values));
    default:
      // OpenSim's GCVSpline(3, ...): degree 3 is half order 2; error variance 0 interpolates.
      return std::make_shared<functions::GCVSpline>(2, data.time, std::move(values), 0.0);
  }
}

}  // namespace sinew::io

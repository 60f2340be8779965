#include <sinew/functions/constant.h>
#include <sinew/functions/control_linear.h>
#include <sinew/io/internal/xml_document.h>
#include <sinew/io/read_controls.h>
#include <sinew/io/storage.h>

#include <memory>
#include <utility>
#include <vector>

namespace sinew::io {
namespace {

constexpr std::string_view kExcitationSuffix = ".excitation";

// The actuator a control drives: OpenSim names controls after the actuator, with ".excitation"
// appended for muscles and most tools' output.
std::string ActuatorOfControl(std::string name) {
  if (name.size() > kExcitationSuffix.size() &&
      name.compare(name.size() - kExcitationSuffix.size(), kExcitationSuffix.size(),
                   kExcitationSuffix) == 0) {
    name.resize(name.size() - kExcitationSuffix.size());
  }
  return name;
}

bool ReadOptionalBool(const internal::XmlDocument& doc, const pugi::xml_node& parent,
                      const char* tag, const std::string& component, bool fallback) {
  const pugi::xml_node node = parent.child(tag);
  return node ? doc.ReadBool(node, component) : fallback;
}

functions::FunctionPtr ReadControlLinear(const internal::XmlDocument& doc,
                                         const pugi::xml_node& control,
                                         const std::string& component) {
  std::vector<double> times, values;
  for (const pugi::xml_node& node : control.child("x_nodes").children("ControlLinearNode")) {
    const pugi::xml_node t = node.child("t");
    const pugi::xml_node v = node.child("value");
    if (!t || !v) doc.Fail(node, component, "ControlLinearNode needs <t> and <value>");
    times.push_back(doc.ReadDouble(t, component));
    values.push_back(doc.ReadDouble(v, component));
    if (times.size() > 1 && !(times.back() > times[times.size() - 2])) {
      doc.Fail(node, component, "ControlLinearNode times must increase");
    }
  }
  if (times.empty()) doc.Fail(control, component, "the control has no <x_nodes>");
  return std::make_shared<functions::ControlLinear>(
      std::move(times), std::move(values),
      ReadOptionalBool(doc, control, "use_steps", component, false),
      ReadOptionalBool(doc, control, "extrapolate", component, true));
}

// A ControlConstant: its `value` at every time (0 when absent, as in OpenSim).
functions::FunctionPtr ReadControlConstant(const internal::XmlDocument& doc,
                                           const pugi::xml_node& control,
                                           const std::string& component) {
  const pugi::xml_node value = control.child("value");
  return std::make_shared<functions::Constant>(value ? doc.ReadDouble(value, component) : 0.0);
}

// The controls of a parsed ControlSet document.
std::map<std::string, functions::FunctionPtr> ReadControls(const internal::XmlDocument& doc) {
  pugi::xml_node set = doc.root();
  if (std::string_view(set.name()) == "OpenSimDocument") set = set.child("ControlSet");
  if (!set || std::string_view(set.name()) != "ControlSet") {
    doc.Fail(doc.root(), "",
             "not a ControlSet file (root element <" + std::string(doc.root().name()) + ">)");
  }
  std::map<std::string, functions::FunctionPtr> controls;
  for (const pugi::xml_node& control : set.child("objects").children()) {
    if (control.type() != pugi::node_element) continue;
    const std::string name = control.attribute("name").value();
    const std::string component = "/controlset/" + name;
    const std::string_view type = control.name();
    if (type != "ControlLinear" && type != "ControlConstant") {
      doc.Fail(control, component,
               "control type <" + std::string(type) +
                   "> is not supported (ControlLinear and ControlConstant are)");
    }
    const std::string actuator = ActuatorOfControl(name);
    functions::FunctionPtr function = type == "ControlLinear"
                                          ? ReadControlLinear(doc, control, component)
                                          : ReadControlConstant(doc, control, component);
    if (!controls.emplace(actuator, std::move(function)).second) {
      doc.Fail(control, component, "a second control for actuator '" + actuator + "'");
    }
  }
  return controls;
}

// A storage table of controls (OpenSim's ControlSet(Storage)): each column a ControlLinear
// through its value at every row, named by its label.
std::map<std::string, functions::FunctionPtr> ReadControlTable(const std::string& file) {
  const Storage table = ReadStorage(file);
  for (int row = 1; row < table.NumRows(); ++row) {
    if (!(table.time[row] > table.time[row - 1])) {
      throw Error({file, 0}, "",
                  "the controls table's times must increase (row " + std::to_string(row + 1) + ")");
    }
  }
  if (table.NumRows() == 0) throw Error({file, 0}, "", "the controls table has no rows");
  std::map<std::string, functions::FunctionPtr> controls;
  for (int column = 0; column < table.NumColumns(); ++column) {
    std::vector<double> values(table.NumRows());
    for (int row = 0; row < table.NumRows(); ++row) values[row] = table.Value(row, column);
    const std::string actuator = ActuatorOfControl(table.labels[column]);
    auto control =
        std::make_shared<functions::ControlLinear>(table.time, std::move(values), false, true);
    if (!controls.emplace(actuator, std::move(control)).second) {
      throw Error({file, 0}, table.labels[column],
                  "a second control for actuator '" + actuator + "'");
    }
  }
  return controls;
}

}  // namespace

std::map<std::string, functions::FunctionPtr> ReadControlSet(const std::string& file) {
  // OpenSim reads a name containing ".sto" as a storage table (ControlSetController).
  if (file.rfind(".sto") != std::string::npos) return ReadControlTable(file);
  return ReadControls(internal::XmlDocument::Load(file));
}

std::map<std::string, functions::FunctionPtr> ParseControlSet(std::string text,
                                                              const std::string& file) {
  return ReadControls(internal::XmlDocument::Parse(std::move(text), file));
}

}  // namespace sinew::io

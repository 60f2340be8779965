// ForwardTool setup files. Property names, defaults and the version upgrades follow OpenSim's
// AbstractTool and ForwardTool (read to learn their semantics; the code is Sinew's own).
#include <sinew/io/forward_setup.h>
#include <sinew/io/internal/osim_context.h>
#include <sinew/io/internal/xml_document.h>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string_view>

namespace sinew::io {
namespace {

using internal::XmlDocument;

// OpenSim renamed these properties (AbstractTool::updateFromXMLNode); both names are read.
constexpr int kVersionActuatorNames = 10904;  // replace_actuator_set, actuator_set_files

std::string FormatNumber(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

bool IsUnassigned(std::string_view text) { return text.empty() || text == "Unassigned"; }

// `text` as written when absolute, else relative to the setup's folder; "" stays "".
std::string Resolve(const std::string& setup_file, std::string_view text) {
  if (IsUnassigned(text)) return "";
  const std::filesystem::path path{std::string(text)};
  if (path.is_absolute()) return path.string();
  return (std::filesystem::path(setup_file).parent_path() / path).lexically_normal().string();
}

// The folder a relative path resolves in (the setup's folder, "." for a bare name).
std::string SetupFolder(const std::string& setup_file) {
  const std::filesystem::path folder = std::filesystem::path(setup_file).parent_path();
  return folder.empty() ? "." : folder.string();
}

int ReadVersion(const XmlDocument& doc, const pugi::xml_node& root) {
  const std::string_view text = root.attribute("Version").value();
  int version = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), version);
  if (!text.empty() && (ec != std::errc() || end != text.data() + text.size() || version <= 0)) {
    doc.Fail(root, "", "OpenSimDocument Version '" + std::string(text) + "' is not a number");
  }
  return version;
}

// Reads every child of the <ForwardTool> element into `setup`.
class SetupReader {
 public:
  SetupReader(const XmlDocument& doc, ForwardSetup& setup) : doc_(doc), setup_(setup) {}

  void Read(const pugi::xml_node& tool) {
    for (const pugi::xml_node& child : tool.children()) {
      if (child.type() == pugi::node_element) ReadProperty(child);
    }
    if (!(setup_.final_time > setup_.initial_time)) {
      doc_.Fail(tool.child("final_time") ? tool.child("final_time") : tool, Component(),
                "final_time (" + FormatNumber(setup_.final_time) +
                    ") must be after initial_time (" + FormatNumber(setup_.initial_time) + ")");
    }
    if (setup_.results_directory.empty()) setup_.results_directory = SetupFolder(setup_.file);
  }

 private:
  std::string Component() const { return "/" + setup_.name; }

  void Warn(const pugi::xml_node& node, const std::string& message) {
    setup_.warnings.push_back({doc_.Where(node), Component(), message});
  }

  void Note(const pugi::xml_node& node, const std::string& message) {
    setup_.notes.push_back({doc_.Where(node), Component(), message});
  }

  double ReadPositive(const pugi::xml_node& node) const {
    const double value = doc_.ReadDouble(node, Component());
    if (!(value > 0)) {
      doc_.Fail(node, Component(), "<" + std::string(node.name()) + "> must be positive");
    }
    return value;
  }

  int ReadCount(const pugi::xml_node& node) const {
    const double value = ReadPositive(node);
    if (value != std::floor(value) || value > 2e9) {
      doc_.Fail(node, Component(),
                "<" + std::string(node.name()) + "> expects a whole number of at most 2e9");
    }
    return static_cast<int>(value);
  }

  void ReadProperty(const pugi::xml_node& node) {
    const std::string_view tag = node.name();
    const std::string_view text = XmlDocument::Text(node);
    if (tag == "model_file") {
      setup_.model_file = Resolve(setup_.file, text);
    } else if (tag == "replace_force_set" || tag == "replace_actuator_set") {
      setup_.replace_force_set = doc_.ReadBool(node, Component());
    } else if (tag == "force_set_files" || tag == "actuator_set_files") {
      ReadFileList(text);
    } else if (tag == "results_directory") {
      setup_.results_directory = Resolve(setup_.file, text);
    } else if (tag == "output_precision") {
      setup_.output_precision = ReadCount(node);
    } else if (tag == "initial_time") {
      setup_.initial_time = doc_.ReadDouble(node, Component());
    } else if (tag == "final_time") {
      setup_.final_time = doc_.ReadDouble(node, Component());
    } else if (tag == "solve_for_equilibrium_for_auxiliary_states") {
      setup_.solve_for_equilibrium_for_auxiliary_states = doc_.ReadBool(node, Component());
    } else if (tag == "maximum_number_of_integrator_steps") {
      setup_.maximum_number_of_integrator_steps = ReadCount(node);
    } else if (tag == "maximum_integrator_step_size") {
      setup_.maximum_integrator_step_size = ReadPositive(node);
    } else if (tag == "minimum_integrator_step_size") {
      setup_.minimum_integrator_step_size = ReadPositive(node);
    } else if (tag == "integrator_error_tolerance") {
      setup_.integrator_error_tolerance = ReadPositive(node);
    } else if (tag == "AnalysisSet") {
      ReadAnalyses(node);
    } else if (tag == "ControllerSet") {
      for (const pugi::xml_node& controller : internal::ObjectsOf(node)) ReadController(controller);
    } else if (tag == "controls_file") {
      // Before 1.9.4 the tool named its controls directly; OpenSim makes a ControlSetController.
      if (!IsUnassigned(text)) SetControlsFile(node, text);
    } else if (tag == "external_loads_file") {
      ReadExternalLoadsFile(node, text);
    } else if (tag == "states_file") {
      setup_.states_file = Resolve(setup_.file, text);
    } else if (tag == "use_specified_dt") {
      if (doc_.ReadBool(node, Component())) {
        doc_.Fail(node, Component(),
                  "use_specified_dt true (time steps taken from the states file) is not "
                  "supported: set it to false to let the integrator choose its steps");
      }
    } else if (tag == "defaults") {
      // Default objects of the setup's own classes: nothing a forward run uses.
    } else if (IsCorrectiveSpringSetting(tag)) {
      ReadCorrectiveSpringSetting(node);
    } else if (tag == "external_loads_model_kinematics_file" ||
               tag == "lowpass_cutoff_frequency_for_load_kinematics" ||
               tag == "external_loads_body1" || tag == "external_loads_body2") {
      if (!IsUnassigned(text)) Note(node, "<" + std::string(tag) + "> ignored, as OpenSim 4 does");
    } else {
      Warn(node, "unknown setting <" + std::string(tag) + "> ignored");
    }
  }

  void ReadFileList(std::string_view text) {
    setup_.force_set_files.clear();
    size_t i = 0;
    while (i < text.size()) {
      const size_t start = text.find_first_not_of(" \t\r\n", i);
      if (start == std::string_view::npos) break;
      size_t end = text.find_first_of(" \t\r\n", start);
      if (end == std::string_view::npos) end = text.size();
      const std::string file = Resolve(setup_.file, text.substr(start, end - start));
      if (!file.empty()) setup_.force_set_files.push_back(file);
      i = end;
    }
  }

  void ReadAnalyses(const pugi::xml_node& set) {
    for (const pugi::xml_node& analysis : internal::ObjectsOf(set)) {
      if (!internal::ReadBoolOr(doc_, analysis, "on", Component(), true)) continue;
      const std::string name = internal::NameOf(analysis);
      Warn(analysis, "analysis " + std::string(analysis.name()) +
                         (name.empty() ? "" : " '" + name + "'") +
                         " is not run (a forward run writes the states, controls and forces "
                         "tables only); it does not change the motion");
    }
  }

  // 4.x `enabled`, 3.x `isDisabled`, 2.x `enable_controller`.
  bool IsControllerEnabled(const pugi::xml_node& controller) const {
    if (pugi::xml_node old = controller.child("enable_controller")) {
      return doc_.ReadBool(old, Component());
    }
    return internal::ReadEnabledFlag(doc_, controller, "enabled", Component(), true);
  }

  void ReadController(const pugi::xml_node& controller) {
    const std::string_view type = controller.name();
    const std::string component = Component() + "/" + internal::NameOf(controller);
    if (!IsControllerEnabled(controller)) {
      Note(controller, "controller <" + std::string(type) + "> is disabled in the setup: ignored");
      return;
    }
    if (type != "ControlSetController") {
      doc_.Fail(controller, component,
                "controller <" + std::string(type) +
                    "> is not supported (only ControlSetController): remove it or disable it");
    }
    const pugi::xml_node file = controller.child("controls_file");
    if (!file || IsUnassigned(XmlDocument::Text(file))) {
      // OpenSim disables a ControlSetController without a file, with a warning.
      Note(controller, "ControlSetController names no controls_file: disabled, as in OpenSim");
      return;
    }
    if (const pugi::xml_node list = controller.child("actuator_list");
        list && !XmlDocument::Text(list).empty() && XmlDocument::Text(list) != "ALL") {
      Note(list,
           "<actuator_list> ignored: each control drives the actuator it is named after, "
           "as OpenSim 4 connects them");
    }
    SetControlsFile(file, XmlDocument::Text(file));
  }

  void SetControlsFile(const pugi::xml_node& node, std::string_view text) {
    if (!setup_.controls_file.empty()) {
      doc_.Fail(node, Component(),
                "a second controls file ('" + std::string(text) +
                    "'): OpenSim adds the controls of several ControlSetControllers; Sinew "
                    "reads one");
    }
    const std::string file = Resolve(setup_.file, text);
    setup_.controls_file = file;
  }

  void ReadExternalLoadsFile(const pugi::xml_node& node, std::string_view text) {
    setup_.external_loads_file = Resolve(setup_.file, text);
    if (!setup_.external_loads_file.empty() &&
        std::filesystem::path(setup_.external_loads_file).extension() != ".xml") {
      doc_.Fail(node, Component(),
                "external_loads_file '" + std::string(text) +
                    "' is not an ExternalLoads .xml file (the pre-2.0 form naming a motion file "
                    "and bodies is not supported)");
    }
  }

  static bool IsCorrectiveSpringSetting(std::string_view tag) {
    return tag.starts_with("body1_") || tag.starts_with("body2_") ||
           tag.starts_with("corrective_spring_") || tag.starts_with("linear_spring_") ||
           tag.starts_with("spring_") || tag == "torsional_spring_scaling_rise_time" ||
           tag == "output_detailed_results";
  }

  // Before 1.9.4 OpenSim turns the corrective springs into a CorrectionController; later
  // versions ignore these settings, and so does Sinew (one note for all of them).
  void ReadCorrectiveSpringSetting(const pugi::xml_node& node) {
    if (setup_.version > 0 && setup_.version < kVersionActuatorNames) {
      doc_.Fail(node, Component(),
                "corrective springs (<" + std::string(node.name()) +
                    ">) become a CorrectionController in OpenSim, which is not supported");
    }
    if (!noted_springs_) {
      Note(node, "corrective spring settings ignored, as OpenSim has since version 1.9.4");
      noted_springs_ = true;
    }
  }

  const XmlDocument& doc_;
  ForwardSetup& setup_;
  bool noted_springs_ = false;
};

ForwardSetup ReadDocument(const XmlDocument& doc) {
  ForwardSetup setup;
  setup.file = doc.file();
  pugi::xml_node tool = doc.root();
  if (std::string_view(tool.name()) == "OpenSimDocument") {
    setup.version = ReadVersion(doc, tool);
    tool = tool.child("ForwardTool");
  }
  if (!tool || std::string_view(tool.name()) != "ForwardTool") {
    doc.Fail(
        doc.root(), "",
        "not a ForwardTool setup file (root element <" + std::string(doc.root().name()) + ">)");
  }
  setup.name = internal::NameOf(tool);
  SetupReader(doc, setup).Read(tool);
  return setup;
}

}  // namespace

ForwardSetup ReadForwardSetup(const std::string& file) {
  return ReadDocument(XmlDocument::Load(file));
}

ForwardSetup ParseForwardSetup(std::string text, const std::string& file) {
  return ReadDocument(XmlDocument::Parse(std::move(text), file));
}

}  // namespace sinew::io

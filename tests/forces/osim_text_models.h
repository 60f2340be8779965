// Small OpenSim 4 models written as text for the forces tests, and parsing them into a System.
#pragma once

#include <sinew/engine/system.h>
#include <sinew/io/osim_reader.h>
#include <sinew/opensim/parser.h>

#include <memory>
#include <string>

namespace sinew::testing {

/// A 2 kg block on a slider along ground's x (coordinate x, default 0.1 m), gravity along -y,
/// with `forces` in its ForceSet.
inline std::string SliderModel(const std::string& forces) {
  return R"(<OpenSimDocument Version="40000"><Model name="slider">
<gravity>0 -9.80665 0</gravity><Ground name="ground"/>
<BodySet><objects><Body name="block"><mass>2</mass><inertia>0.1 0.1 0.1 0 0 0</inertia></Body>
</objects></BodySet>
<JointSet><objects><SliderJoint name="slide"><socket_parent_frame>/ground</socket_parent_frame>
<socket_child_frame>/bodyset/block</socket_child_frame>
<coordinates><Coordinate name="x"><default_value>0.1</default_value></Coordinate></coordinates>
</SliderJoint></objects></JointSet>
<ForceSet><objects>
)" + forces +
         R"(
</objects></ForceSet></Model></OpenSimDocument>)";
}

/// A finalized system parsed from .osim text, with the parser's Report.
struct ParsedModel {
  std::unique_ptr<engine::System> system;
  opensim::Report report;
};

/// Reads `text` as the file `file` (named in errors) and builds it with the OpenSim parser.
inline ParsedModel ParseOsimText(const std::string& text, const std::string& file) {
  opensim::OpenSimParser parser;
  const model::ModelSpec spec = io::ReadOsimString(text, file);
  ParsedModel parsed{std::make_unique<engine::System>(spec.gravity), {}};
  parser.ParseSpec(*parsed.system, spec);
  parsed.system->Finalize();
  parsed.report = parser.GetReport();
  return parsed;
}

}  // namespace sinew::testing

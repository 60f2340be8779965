// A 2 kg block on a slider with a path from ground to it, and parsing such a model from text
// (or a model file): the small musculoskeletal system the muscle tests run their models on.
#pragma once

#include <sinew/engine/system.h>
#include <sinew/io/osim_reader.h>
#include <sinew/opensim/parser.h>

#include <memory>
#include <string>

namespace sinew::muscles {

// A 2 kg block on a slider along ground's x (coordinate x, default 0.1 m, `locked` or not),
// with `forces` in its ForceSet; no gravity along the slider.
inline std::string SliderModel(const std::string& forces, bool locked) {
  return std::string(R"(<OpenSimDocument Version="40000"><Model name="slider">
<gravity>0 -9.80665 0</gravity><Ground name="ground"/>
<BodySet><objects><Body name="block"><mass>2</mass><inertia>0.1 0.1 0.1 0 0 0</inertia></Body>
</objects></BodySet>
<JointSet><objects><SliderJoint name="slide"><socket_parent_frame>/ground</socket_parent_frame>
<socket_child_frame>/bodyset/block</socket_child_frame>
<coordinates><Coordinate name="x"><default_value>0.1</default_value><locked>)") +
         (locked ? "true" : "false") + R"(</locked></Coordinate></coordinates>
</SliderJoint></objects></JointSet>
<ForceSet><objects>
)" + forces +
         R"(
</objects></ForceSet></Model></OpenSimDocument>)";
}

// A path from ground at x = -0.3 m to the block's origin: length 0.4 m at x = 0.1 m.
inline constexpr char kPath[] = R"(<GeometryPath><PathPointSet><objects>
<PathPoint name="p1"><socket_parent_frame>/ground</socket_parent_frame><location>-0.3 0 0</location></PathPoint>
<PathPoint name="p2"><socket_parent_frame>/bodyset/block</socket_parent_frame><location>0 0 0</location></PathPoint>
</objects></PathPointSet></GeometryPath>)";

struct Parsed {
  opensim::OpenSimParser parser;
  std::unique_ptr<engine::System> system;
};

inline std::unique_ptr<Parsed> Parse(const std::string& text, bool equilibrate = false) {
  auto parsed = std::make_unique<Parsed>();
  parsed->parser.EquilibrateMuscles(equilibrate);
  const model::ModelSpec spec = io::ReadOsimString(text, "muscle_test.osim");
  parsed->system = std::make_unique<engine::System>(spec.gravity);
  parsed->parser.ParseSpec(*parsed->system, spec);
  parsed->system->Finalize();
  return parsed;
}

// The same from a file.
inline std::unique_ptr<Parsed> ParseFile(const std::string& file, bool equilibrate = false) {
  auto parsed = std::make_unique<Parsed>();
  parsed->parser.EquilibrateMuscles(equilibrate);
  const model::ModelSpec spec = io::ReadOsim(file);
  parsed->system = std::make_unique<engine::System>(spec.gravity);
  parsed->parser.ParseSpec(*parsed->system, spec);
  parsed->system->Finalize();
  return parsed;
}

}  // namespace sinew::muscles

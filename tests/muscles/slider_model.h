// A 2 kg block on a slider with a path from ground to it, and parsing such a model from text
// (or a model file): the small musculoskeletal system the muscle tests run their models on.
#pragma once

#include <gtest/gtest.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/energy.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/system.h>
#include <sinew/io/osim_reader.h>
#include <sinew/opensim/parser.h>

#include <cmath>
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

// A PathSpring on `path` (a path of length 0.4 m at x = 0.1 m whose length grows with x, such as
// kPath), k = 50 N/m, resting length 0.3 m: the 2 kg block from x = 0.1 m follows
// x = 0.1 cos(5 t) while the spring is stretched (x > 0, t < pi / 10 s), conserving energy.
inline void ExpectStretchedSpringOscillatesAsTheClosedForm(const std::string& path) {
  auto parsed =
      Parse(SliderModel(std::string(R"(<PathSpring name="spring">)") + path +
                            "<resting_length>0.3</resting_length><stiffness>50</stiffness>"
                            "<dissipation>0</dissipation></PathSpring>",
                        false));
  auto integrator = engine::MakeIntegrator("rk45", *parsed->system, {.accuracy = 1e-11});
  engine::State state = engine::MakeDefaultState(*parsed->system);
  const double energy0 = engine::CalcMechanicalEnergy(*parsed->system, state);
  EXPECT_NEAR(energy0, 0.5 * 50 * 0.1 * 0.1, 1e-12);  // the slider at y = 0: no gravity term
  for (double t : {0.1, 0.2, 0.3}) {
    integrator->StepTo(state, t);
    EXPECT_NEAR(engine::GetCoordinateValue(*parsed->system, state, "x"), 0.1 * std::cos(5 * t),
                1e-10)
        << t;
    EXPECT_NEAR(engine::CalcMechanicalEnergy(*parsed->system, state), energy0, 1e-10) << t;
  }
}

}  // namespace sinew::muscles

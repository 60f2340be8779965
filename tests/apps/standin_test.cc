// A joint type the engine cannot model (an unknown class, or ConstantCurvatureJoint) becomes a
// spherical stand-in, and every command agrees on which joints those are (one function,
// opensim::ReplaceWithStandIns, decides): inspect's build report, and the warnings of
// kinematics, simulate and export. simulate runs (it used to
// stop with an internal Storage::AppendRow error) and starts where kinematics puts the bodies.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <string>

#include "apps/cli_test_util.h"
#include "engine/test_models.h"

namespace sinew {
namespace {

using engine::testing::ReadStoColumns;
using testing::CliRun;

const std::string kResources = std::string(SINEW_TEST_DATA_DIR) +
                               "/opensim-org/opensim-core/Applications/Analyze/tests/resources/";

// The joint names in every "... replaced by a spherical stand-in (/jointset/a: T, ...)" of
// `err`, and how many such lines there are.
std::set<std::string> StandInsNamed(const std::string& err, int* lines) {
  std::set<std::string> names;
  *lines = 0;
  const std::regex line(R"(replaced by a spherical stand-in \(([^)]*)\))");
  const std::regex joint(R"(/jointset/([^:,]+): )");
  for (auto it = std::sregex_iterator(err.begin(), err.end(), line); it != std::sregex_iterator();
       ++it) {
    ++*lines;
    const std::string list = (*it)[1].str();
    for (auto j = std::sregex_iterator(list.begin(), list.end(), joint);
         j != std::sregex_iterator(); ++j) {
      names.insert((*j)[1].str());
    }
  }
  return names;
}

class StandInTest : public testing::CliTest {
 protected:
  // DoublePendulum3D with its second joint (pin2, a CustomJoint) retyped as a class no one
  // knows: the file is the same otherwise.
  std::string WriteModel() const {
    std::string text = testing::ReadText(kResources + "DoublePendulum3D.osim");
    const std::string open = "<CustomJoint name=\"pin2\">";
    const size_t at = text.find(open);
    EXPECT_NE(at, std::string::npos);
    text.replace(at, open.size(), "<FancyJoint name=\"pin2\">");
    const std::string close = "</CustomJoint>";
    const size_t end = text.find(close, at);
    text.replace(end, close.size(), "</FancyJoint>");
    const std::string file = Path("fancy.osim");
    std::ofstream(file) << text;
    return file;
  }

  // Runs inspect, kinematics (into kin/), simulate (into sim/) and export on `model` and
  // checks that each names exactly the joints `expected` as stand-ins, in one line.
  void ExpectAllNameTheStandIns(const std::string& model,
                                const std::set<std::string>& expected) const {
    const CliRun inspect = Run("inspect --json " + model);
    ASSERT_EQ(inspect.exit_code, 0) << inspect.err;
    std::set<std::string> from_inspect;
    const nlohmann::json report = nlohmann::json::parse(inspect.out);
    for (const auto& joint : report.at("build").at("joints")) {
      if (joint.at("standin").get<bool>()) {
        from_inspect.insert(joint.at("name").get<std::string>());
      }
    }
    EXPECT_EQ(from_inspect, expected);
    const std::string commands[] = {
        "kinematics " + model + " --out " + Path("kin"),
        "simulate " + model + " --duration 0.2 --accuracy 1e-9 --quiet --out " + Path("sim"),
        "export " + model + " --vis primitives --out " + Path("model.glb")};
    for (const std::string& command : commands) {
      const CliRun run = Run(command);
      ASSERT_EQ(run.exit_code, 0) << command << "\n" << run.err;
      int lines = 0;
      EXPECT_EQ(StandInsNamed(run.err, &lines), expected) << command << "\n" << run.err;
      EXPECT_EQ(lines, 1) << command << "\n" << run.err;
    }
  }
};

TEST_F(StandInTest, InspectKinematicsSimulateAndExportNameTheSameJoints) {
  const std::string model = WriteModel();
  ExpectAllNameTheStandIns(model, {"pin2"});
  if (HasFatalFailure()) return;
  // states.sto holds the stand-in's three coordinates in place of pin2's r2_x.
  const auto states = ReadStoColumns(Path("sim/states.sto"));
  EXPECT_EQ(states.count("/jointset/pin2/r2_x/value"), 0u);
  for (const char* axis : {"x", "y", "z"}) {
    const std::string label = std::string("/jointset/pin2/pin2_standin_r") + axis + "/value";
    ASSERT_EQ(states.count(label), 1u) << label;
    EXPECT_EQ(states.at(label).front(), 0.0) << label;  // frames coincide at the start
  }
  // At t = 0 the simulation's bodies are where kinematics puts them (both hold the stand-in's
  // frames together and pin1 at its default), computed by the engine and the kinematic tree.
  const auto sim_bodies = ReadStoColumns(Path("sim/bodies.sto"));
  const auto kin_bodies = ReadStoColumns(Path("kin/bodies.sto"));
  for (const char* column : {"rod2_X", "rod2_Y", "rod2_Z", "rod1_X", "rod1_Y"}) {
    ASSERT_EQ(sim_bodies.count(column), 1u) << column;
    EXPECT_NEAR(sim_bodies.at(column).front(), kin_bodies.at(column).front(), 1e-12) << column;
  }
  // And pin1 swings under gravity: the run is a real one.
  EXPECT_GT(std::abs(states.at("/jointset/pin1/r1_z/value").back() -
                     states.at("/jointset/pin1/r1_z/value").front()),
            1e-3);
}

// ConstantCurvatureJoint is an OpenSim class the reader knows but nothing in Sinew models: it
// is a stand-in too (inspect used to call it simulated while simulate failed on it). The stand-
// in holds the link's frame at the joint's parent frame, 1 m above the origin, so its mass
// centre (0.5 m below its origin) starts at (0, 0.5, 0).
TEST_F(StandInTest, AKnownButUnmodelledJointIsAStandInEverywhere) {
  const std::string model = Path("bend.osim");
  std::ofstream(model) << R"(<?xml version="1.0" encoding="UTF-8" ?>
<OpenSimDocument Version="40000">
  <Model name="bend">
    <gravity>0 -9.81 0</gravity>
    <BodySet name="bodyset"><objects>
      <Body name="link">
        <mass>2</mass><mass_center>0 -0.5 0</mass_center><inertia>0.1 0.1 0.1 0 0 0</inertia>
      </Body>
    </objects></BodySet>
    <JointSet name="jointset"><objects>
      <ConstantCurvatureJoint name="bend">
        <socket_parent_frame>ground_offset</socket_parent_frame>
        <socket_child_frame>link_offset</socket_child_frame>
        <coordinates><Coordinate name="k1"/><Coordinate name="k2"/><Coordinate name="k3"/>
        </coordinates>
        <length>0.1</length>
        <frames>
          <PhysicalOffsetFrame name="ground_offset"><socket_parent>/ground</socket_parent>
            <translation>0 1 0</translation><orientation>0 0 0</orientation>
          </PhysicalOffsetFrame>
          <PhysicalOffsetFrame name="link_offset"><socket_parent>/bodyset/link</socket_parent>
            <translation>0 0 0</translation><orientation>0 0 0</orientation>
          </PhysicalOffsetFrame>
        </frames>
      </ConstantCurvatureJoint>
    </objects></JointSet>
  </Model>
</OpenSimDocument>
)";
  ExpectAllNameTheStandIns(model, {"bend"});
  if (HasFatalFailure()) return;
  for (const char* file : {"kin/bodies.sto", "sim/bodies.sto"}) {
    const auto bodies = ReadStoColumns(Path(file));
    EXPECT_NEAR(bodies.at("link_X").front(), 0.0, 1e-12) << file;
    EXPECT_NEAR(bodies.at("link_Y").front(), 0.5, 1e-12) << file;
    EXPECT_NEAR(bodies.at("link_Z").front(), 0.0, 1e-12) << file;
  }
}

}  // namespace
}  // namespace sinew

// Forces switched off (appliesForce false in the file, OpenSimParser::DisableForce) and an
// ExternalForce inside a model's ForceSet, through the parser: what is built, what the Report
// says, and the motion that results.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/integrator.h>
#include <sinew/io/osim_reader.h>
#include <sinew/opensim/parser.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

namespace sinew {
namespace {

const std::string kData = SINEW_TEST_DATA_DIR;
const std::string kForward =
    kData + "/opensim-org/opensim-core/Applications/Forward/tests/resources/";

std::string ReadText(const std::string& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// `file`'s text with `forces` as the objects of its (empty) ForceSet.
std::string WithForces(const std::string& file, const std::string& forces) {
  std::string text = ReadText(file);
  const std::string empty = "<ForceSet name=\"\">\n\t\t\t<objects/>";
  const size_t at = text.find(empty);
  EXPECT_NE(at, std::string::npos);
  text.replace(at, empty.size(), "<ForceSet name=\"\"><objects>" + forces + "</objects>");
  return text;
}

// Expects `call` to throw a sinew::Error whose message contains `part`.
template <typename Call>
void ExpectError(const Call& call, const std::string& part) {
  try {
    call();
    ADD_FAILURE() << "no error; expected: " << part;
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find(part), std::string::npos) << error.what();
  }
}

// The pendulum's angle at t = 1 s (rk45, accuracy 1e-10).
double AngleAfterOneSecond(const engine::System& system) {
  engine::IntegratorSettings settings;
  settings.accuracy = 1e-10;
  auto integrator = engine::MakeIntegrator("rk45", system, settings);
  engine::State state = engine::MakeDefaultState(system);
  integrator->StepTo(state, 1.0);
  return state.q[system.FindCoordinate("Pendulum_r1")];
}

TEST(ForceSwitchesTest, AForceOffInTheFileOrByNameIsDisabledNotMissing) {
  // A spring off in the file, and a muscle (not simulated by Sinew) disabled by name.
  const std::string text = WithForces(
      kForward + "pendulum_no_gravity.osim",
      "<SpringGeneralizedForce name=\"spring\"><appliesForce>false</appliesForce>"
      "<coordinate>Pendulum_r1</coordinate><stiffness>100</stiffness></SpringGeneralizedForce>"
      "<Thelen2003Muscle name=\"musc\"/>");
  opensim::OpenSimParser parser;
  parser.DisableForce("musc");
  parser.SetStrict(true);  // a switched-off force is not an omission
  engine::System system;
  parser.ParseSpec(system, io::ReadOsimString(text, kForward + "inline.osim"));
  system.Finalize();
  const opensim::ForceInfo* spring = parser.GetReport().GetForce("spring");
  ASSERT_NE(spring, nullptr);
  EXPECT_EQ(spring->load, nullptr);
  EXPECT_EQ(spring->disabled, "appliesForce false in the file");
  EXPECT_EQ(parser.GetReport().GetForce("musc")->disabled, "disabled by name");
  EXPECT_TRUE(parser.GetReport().not_simulated().empty());
  EXPECT_TRUE(system.force_elements().empty());
}

TEST(ForceSwitchesTest, DisableForceByNameLeavesItOutOrListsCloseNames) {
  opensim::OpenSimParser parser;
  parser.DisableForce("block_spring");
  auto system = parser.Parse(kData + "/sinew/springs.osim");
  const opensim::ForceInfo* spring = parser.GetReport().GetForce("block_spring");
  ASSERT_NE(spring, nullptr);
  EXPECT_EQ(spring->load, nullptr);
  EXPECT_EQ(spring->disabled, "disabled by name");
  EXPECT_NE(parser.GetReport().GetForce("arm_spring")->load, nullptr);
  EXPECT_EQ(system->force_elements().size(), 2u);  // arm_limit and arm_spring

  opensim::OpenSimParser typo;
  typo.DisableForce("arm_sprin");
  ExpectError([&] { typo.Parse(kData + "/sinew/springs.osim"); },
              "arm_sprin: cannot disable: no force has this name (close names: arm_spring");
}

TEST(ForceSwitchesTest, ExternalForceInTheForceSetReadsItsDataSourceBesideTheModel) {
  // The ExternalForce of pendulum_external_load.xml moved into the model: the same force as
  // gravity on the 10 kg pendulum, so the swing is pendulum.osim's.
  const std::string force =
      "<ExternalForce name=\"gravity\"><applied_to_body>pendulum</applied_to_body>"
      "<force_expressed_in_body>ground</force_expressed_in_body>"
      "<point_expressed_in_body>pendulum</point_expressed_in_body>"
      "<force_identifier>force</force_identifier><point_identifier>point</point_identifier>"
      "<torque_identifier>torque</torque_identifier>"
      "<data_source_name>pendulum_external_load.sto</data_source_name></ExternalForce>";
  opensim::OpenSimParser parser;
  engine::System system;
  parser.ParseSpec(system,
                   io::ReadOsimString(WithForces(kForward + "pendulum_no_gravity.osim", force),
                                      kForward + "inline.osim"));
  system.Finalize();
  EXPECT_NE(parser.GetReport().GetForce("gravity")->load, nullptr);
  opensim::OpenSimParser gravity_parser;
  const auto gravity = gravity_parser.Parse(kForward + "pendulum.osim");
  EXPECT_NEAR(AngleAfterOneSecond(system), AngleAfterOneSecond(*gravity), 1e-6);

  // Without data it is refused, naming the force.
  const std::string no_data =
      "<ExternalForce name=\"push\"><applied_to_body>pendulum</applied_to_body>"
      "<force_identifier>force</force_identifier></ExternalForce>";
  engine::System other;
  ExpectError(
      [&] {
        parser.ParseSpec(
            other, io::ReadOsimString(WithForces(kForward + "pendulum_no_gravity.osim", no_data),
                                      kForward + "inline.osim"));
      },
      "/forceset/push: an ExternalForce in the ForceSet has no data");
}

TEST(ForceSwitchesTest, AnUnknownExpressedInBodyIsGroundWithAWarningButAPathIsRefused) {
  // OpenSim warns and uses ground for a force_expressed_in_body naming no body; a path that
  // names no body may be an offset frame OpenSim would use, which Sinew refuses.
  auto force = [](const std::string& frame) {
    return "<ExternalForce name=\"push\"><applied_to_body>pendulum</applied_to_body>"
           "<force_expressed_in_body>" +
           frame +
           "</force_expressed_in_body><force_identifier>force</force_identifier>"
           "<data_source_name>pendulum_external_load.sto</data_source_name></ExternalForce>";
  };
  opensim::OpenSimParser parser;
  engine::System system;
  parser.ParseSpec(system, io::ReadOsimString(
                               WithForces(kForward + "pendulum_no_gravity.osim", force("nowhere")),
                               kForward + "inline.osim"));
  EXPECT_NE(parser.GetReport().GetForce("push")->load, nullptr);
  bool warned = false;
  for (const Diagnostic& w : parser.GetReport().warnings()) {
    warned = warned || w.message.find("'nowhere' is not a body of the model: ground is used") !=
                           std::string::npos;
  }
  EXPECT_TRUE(warned);
  engine::System other;
  ExpectError(
      [&] {
        parser.ParseSpec(other, io::ReadOsimString(WithForces(kForward + "pendulum_no_gravity.osim",
                                                              force("/bodyset/pendulum/offset")),
                                                   kForward + "inline.osim"));
      },
      "force_expressed_in_body '/bodyset/pendulum/offset' is not a body of the model");
}

}  // namespace
}  // namespace sinew

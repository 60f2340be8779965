// ForwardTool setup files (io::ReadForwardSetup) in OpenSim's layouts, and the ForceSet files a
// setup adds to its model (io::ReadOsim with ForceSetFiles).
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/io/forward_setup.h>
#include <sinew/io/osim_reader.h>
#include <sinew/model/element_values.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace sinew::io {
namespace {

const std::string kForward = std::string(SINEW_TEST_DATA_DIR) +
                             "/opensim-org/opensim-core/Applications/Forward/tests/resources/";

// The message of the sinew::Error `read` throws ("" when it throws none).
template <typename F>
std::string ErrorOf(F read) {
  try {
    read();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// A setup in `folder` (relative paths resolve there) whose ForwardTool holds `body`.
ForwardSetup ParseTool(const std::string& body, int version = 40000,
                       const std::string& folder = "/setups") {
  return ParseForwardSetup("<OpenSimDocument Version=\"" + std::to_string(version) +
                               "\">\n<ForwardTool name=\"run\">\n" + body +
                               "\n</ForwardTool>\n</OpenSimDocument>\n",
                           folder + "/run_Setup_Forward.xml");
}

TEST(ForwardSetupTest, ReadsSubject01WithPathsRelativeToTheSetup) {
  const ForwardSetup setup = ReadForwardSetup(kForward + "subject01_Setup_Forward.xml");
  const std::filesystem::path folder = std::filesystem::path(kForward).lexically_normal();
  const auto in_folder = [&](const char* name) { return (folder / name).string(); };
  EXPECT_EQ(setup.name, "subject01");
  EXPECT_EQ(setup.version, 20302);
  EXPECT_EQ(setup.model_file, in_folder("subject01_adjusted.osim"));
  EXPECT_FALSE(setup.replace_force_set);
  ASSERT_EQ(setup.force_set_files.size(), 1u);
  EXPECT_EQ(setup.force_set_files[0], in_folder("gait2354_CMC_Actuators.xml"));
  EXPECT_EQ(setup.results_directory, in_folder("Results"));
  EXPECT_EQ(setup.output_precision, 20);
  EXPECT_EQ(setup.initial_time, 0.8);
  EXPECT_EQ(setup.final_time, 0.95);
  EXPECT_FALSE(setup.solve_for_equilibrium_for_auxiliary_states);
  EXPECT_EQ(setup.maximum_number_of_integrator_steps, 30000);
  EXPECT_EQ(setup.maximum_integrator_step_size, 1.0);
  EXPECT_EQ(setup.minimum_integrator_step_size, 1e-8);
  EXPECT_EQ(setup.integrator_error_tolerance, 1e-5);
  EXPECT_EQ(setup.controls_file, in_folder("subject01_walk1_controls.xml"));
  EXPECT_EQ(setup.external_loads_file, in_folder("subject01_GRFs.xml"));
  EXPECT_EQ(setup.states_file, in_folder("std_subject01_walk1_states.sto"));
  EXPECT_TRUE(setup.notes.empty()) << setup.notes.front().Format();
  EXPECT_TRUE(setup.warnings.empty()) << setup.warnings.front().Format();
}

// OpenSim's defaults for what a setup leaves out; an empty results_directory is the setup's
// folder; absolute paths stay as written.
TEST(ForwardSetupTest, DefaultsAreOpenSims) {
  const ForwardSetup setup = ParseTool("<model_file>/models/m.osim</model_file>");
  EXPECT_EQ(setup.model_file, "/models/m.osim");
  EXPECT_EQ(setup.results_directory, "/setups");
  EXPECT_EQ(setup.initial_time, 0.0);
  EXPECT_EQ(setup.final_time, 1.0);
  EXPECT_EQ(setup.integrator_error_tolerance, 1e-5);
  EXPECT_EQ(setup.maximum_integrator_step_size, 1.0);
  EXPECT_EQ(setup.minimum_integrator_step_size, 1e-8);
  EXPECT_EQ(setup.maximum_number_of_integrator_steps, 20000);
  EXPECT_EQ(setup.output_precision, 8);
  EXPECT_FALSE(setup.replace_force_set);
  EXPECT_TRUE(setup.controls_file.empty());
}

// A ControlSetController is switched off by 4.x `enabled`, 3.x `isDisabled` and 2.x
// `enable_controller` alike; before 1.9.4 the tool itself named the controls file; the old
// names of the force set properties are read.
TEST(ForwardSetupTest, ControllerFlagsAndOldNamesOfEveryLayout) {
  const auto controller = [](const std::string& flag) {
    return "<ControllerSet><objects><ControlSetController>" + flag +
           "<controls_file>c.xml</controls_file></ControlSetController></objects>"
           "</ControllerSet>";
  };
  EXPECT_EQ(ParseTool(controller("")).controls_file, "/setups/c.xml");
  EXPECT_EQ(ParseTool("<ControllerSet><objects><ControlSetController><controls_file>c.sto"
                      "</controls_file></ControlSetController></objects></ControllerSet>")
                .controls_file,
            "/setups/c.sto");
  EXPECT_EQ(ParseTool(controller("<enabled>false</enabled>")).controls_file, "");
  EXPECT_EQ(ParseTool(controller("<isDisabled>true</isDisabled>"), 30000).controls_file, "");
  EXPECT_EQ(
      ParseTool(controller("<enable_controller>false</enable_controller>"), 20300).controls_file,
      "");
  const ForwardSetup old = ParseTool(
      "<controls_file>old.xml</controls_file><replace_actuator_set>true</replace_actuator_set>"
      "<actuator_set_files>a.xml  b.xml</actuator_set_files>",
      10900);
  EXPECT_EQ(old.controls_file, "/setups/old.xml");
  EXPECT_TRUE(old.replace_force_set);
  EXPECT_EQ(old.force_set_files, (std::vector<std::string>{"/setups/a.xml", "/setups/b.xml"}));
}

// What does not change the motion names its line: analyses not run and unknown settings as
// warnings (OpenSim would act on them), corrective spring settings as a note (OpenSim ignores
// them since 1.9.4).
TEST(ForwardSetupTest, SettingsThatDoNotChangeTheMotionAreNotesWithTheirLine) {
  const ForwardSetup setup = ParseTool(
      "<AnalysisSet><objects><Kinematics name=\"k\"><on>true</on></Kinematics>"
      "<Actuation><on>false</on></Actuation></objects></AnalysisSet>\n"
      "<colour>red</colour>\n<body1_linear_corrective_spring_active>false"
      "</body1_linear_corrective_spring_active>");
  ASSERT_EQ(setup.warnings.size(), 2u);
  EXPECT_EQ(setup.warnings[0].where.line, 3);
  EXPECT_NE(setup.warnings[0].message.find("analysis Kinematics 'k' is not run"),
            std::string::npos);
  EXPECT_EQ(setup.warnings[1].Format(),
            "/setups/run_Setup_Forward.xml:4: /run: unknown setting <colour> ignored");
  ASSERT_EQ(setup.notes.size(), 1u);
  EXPECT_EQ(setup.notes[0].where.line, 5);
  EXPECT_NE(setup.notes[0].message.find("corrective spring"), std::string::npos);
}

// What would change the results and is not supported is an error naming file, line and
// element.
TEST(ForwardSetupTest, UnsupportedSettingsAreErrorsWithTheirLine) {
  EXPECT_EQ(ErrorOf([] {
              ParseTool("\n<use_specified_dt>true</use_specified_dt>");
            }).rfind("/setups/run_Setup_Forward.xml:4: /run: use_specified_dt true", 0),
            0u);
  struct Case {
    std::string body;
    std::string error;  // a part of the message
    int version = 40000;
  };
  const std::string controller = "<ControllerSet><objects><ControlSetController><controls_file>";
  const std::string end_controller = "</controls_file></ControlSetController>";
  const Case cases[] = {
      {"<ControllerSet><objects><PrescribedController name=\"p\"/></objects></ControllerSet>",
       "/run/p: controller <PrescribedController> is not supported"},
      {controller + "a.xml" + end_controller + "<ControlSetController><controls_file>b.xml" +
           end_controller + "</objects></ControllerSet>",
       "a second controls file ('b.xml')"},
      {"<external_loads_file>grf.mot</external_loads_file>", "is not an ExternalLoads .xml file"},
      {"<initial_time>2</initial_time><final_time>1</final_time>",
       "final_time (1) must be after initial_time (2)"},
      {"<integrator_error_tolerance>-1</integrator_error_tolerance>",
       "<integrator_error_tolerance> must be positive"},
      {"<body1_linear_corrective_spring_active>true</body1_linear_corrective_spring_active>",
       "CorrectionController", 10900},
  };
  for (const Case& c : cases) {
    EXPECT_NE(ErrorOf([&] { ParseTool(c.body, c.version); }).find(c.error), std::string::npos)
        << c.body;
  }
  EXPECT_NE(ErrorOf([] {
              ParseForwardSetup("<OpenSimDocument><CMCTool/></OpenSimDocument>", "x.xml");
            }).find("not a ForwardTool setup file"),
            std::string::npos);
}

// CMC's actuators are appended to subject01's ForceSet (or replace it), each read as if the
// model held it, with the actuators file's lines.
TEST(ForceSetFilesTest, ActuatorsAreAppendedOrReplaceTheForceSet) {
  const std::string model = kForward + "subject01_adjusted.osim";
  const std::string actuators = kForward + "gait2354_CMC_Actuators.xml";
  const model::ModelSpec plain = ReadOsim(model);
  const model::ModelSpec appended = ReadOsim(model, ForceSetFiles{{actuators}, false});
  ASSERT_EQ(appended.forces.size(), plain.forces.size() + 12);
  const model::ForceSpec& fx = appended.forces[plain.forces.size()];
  EXPECT_EQ(fx.name, "FX");
  EXPECT_EQ(fx.type, "PointActuator");
  EXPECT_EQ(fx.path, "/forceset/FX");
  EXPECT_EQ(fx.where.file, actuators);
  EXPECT_EQ(fx.where.line, 49);  // <PointActuator name="FX"> in the file
  // Each force keeps its document's format version: the model's, and 10500 for the bare
  // <ForceSet> file (no OpenSimDocument), as OpenSim reads it.
  EXPECT_EQ(appended.forces.front().version, 20302);
  EXPECT_EQ(fx.version, 10500);
  EXPECT_EQ(appended.forces.back().name, "mtp_angle_l_reserve");
  const model::ModelSpec replaced = ReadOsim(model, ForceSetFiles{{actuators}, true});
  ASSERT_EQ(replaced.forces.size(), 12u);
  EXPECT_EQ(replaced.forces.front().name, "FX");
}

// A ForceSet file's <defaults> give their values to the objects of the same class that leave
// them out (OpenSim copies the default object, then reads the object's own properties); a
// coordinate the model does not have is an error naming the ForceSet file's line.
TEST(ForceSetFilesTest, DefaultsFillWhatObjectsLeaveOutAndErrorsNameTheFile) {
  const std::filesystem::path dir =
      std::filesystem::path(::testing::TempDir()) / "sinew_force_set_files";
  std::filesystem::create_directories(dir);
  const std::string file = (dir / "actuators.xml").string();
  std::ofstream(file) << "<ForceSet name=\"extra\">\n<defaults>\n"
                         "<CoordinateActuator name=\"default\"><optimal_force>7</optimal_force>"
                         "</CoordinateActuator>\n</defaults>\n<objects>\n"
                         "<CoordinateActuator name=\"a\"><coordinate>knee_angle_r</coordinate>"
                         "</CoordinateActuator>\n"
                         "<CoordinateActuator name=\"b\"><coordinate>knee_angle_r</coordinate>"
                         "<optimal_force>3</optimal_force></CoordinateActuator>\n"
                         "</objects>\n</ForceSet>\n";
  const model::ModelSpec spec =
      ReadOsim(kForward + "subject01_adjusted.osim", ForceSetFiles{{file}, true});
  ASSERT_EQ(spec.forces.size(), 2u);
  const auto optimal_force = [&](const model::ForceSpec& f) {
    return model::ElementValues(f.element, f.where.file, f.path).Double("optimal_force", 1.0);
  };
  EXPECT_EQ(optimal_force(spec.forces[0]), 7.0);
  EXPECT_EQ(optimal_force(spec.forces[1]), 3.0);
  std::ofstream(file) << "<ForceSet>\n<objects>\n<CoordinateActuator name=\"c\">\n"
                         "<coordinate>elbow</coordinate>\n</CoordinateActuator>\n</objects>\n"
                         "</ForceSet>\n";
  EXPECT_EQ(ErrorOf([&] {
              ReadOsim(kForward + "subject01_adjusted.osim", ForceSetFiles{{file}, false});
            }),
            file + ":4: /forceset/c: <coordinate> 'elbow' does not exist");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace sinew::io

// `sinew inspect`: the text summary, the --json object's fields, and exit code 2 with a precise
// message for bad input. Runs the built CLI (SINEW_CLI_PATH).
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "apps/cli_test_util.h"
#include "apps/unsupported_wraps.h"

namespace sinew {
namespace {

using testing::CliRun;

const std::string kArm26 =
    std::string(SINEW_TEST_DATA_DIR) + "/opensim-org/opensim-models/Models/Arm26/arm26.osim";

class Inspect : public testing::CliTest {};

TEST_F(Inspect, TextSummary) {
  const CliRun run = Run("inspect " + kArm26);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("format version: 40000"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("r_shoulder  CustomJoint  base -> r_humerus  [r_shoulder_elev]"),
            std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("Thelen2003Muscle: 6"), std::string::npos) << run.out;
  // The muscles and the wrap objects (cylinders, ellipsoids) are simulated.
  EXPECT_NE(run.out.find("TRIlong                     Thelen2003Muscle      simulated"),
            std::string::npos)
      << run.out;
  EXPECT_EQ(run.out.find("/forceset/TRIlong: Thelen2003Muscle"), std::string::npos) << run.out;
  EXPECT_EQ(run.out.find("/bodyset/r_humerus/wrapobjectset/TRI: WrapCylinder"), std::string::npos)
      << run.out;
}

TEST_F(Inspect, PathsAreListedWithTheirPointsAndWrapsAndWhatIsNotComputed) {
  const CliRun run = Run("inspect " + kArm26);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("paths (6):"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("  TRIlong  5 points (0 conditional, 0 moving), 3 wraps: TRI, "
                         "TRIlonghh, TRIlongglen\n"),
            std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("  BICshort  6 points (0 conditional, 0 moving), 0 wraps\n"),
            std::string::npos)
      << run.out;
  // 7 PathWraps over 5 paths, all over cylinders and ellipsoids: all computed.
  EXPECT_NE(run.out.find("path parts not computed (0):"), std::string::npos) << run.out;
  // The same model with its two ellipsoids made a plugin's MyPluginWrapObject: those 2 PathWraps
  // are named with their path (not applied).
  const CliRun unsupported = Run(
      "inspect " + testing::WriteWithUnsupportedWraps(kArm26, Path("with_unsupported_wraps.osim")));
  ASSERT_EQ(unsupported.exit_code, 0) << unsupported.err;
  EXPECT_NE(unsupported.out.find("path parts not computed (2):"), std::string::npos)
      << unsupported.out;
  EXPECT_NE(
      unsupported.out.find("/forceset/TRIlong: wrap object 'TRIlonghh' (MyPluginWrapObject) is not "
                           "applied yet"),
      std::string::npos)
      << unsupported.out;
  const CliRun json = Run("inspect --json " + kArm26);
  ASSERT_EQ(json.exit_code, 0) << json.err;
  const nlohmann::json j = nlohmann::json::parse(json.out);
  ASSERT_EQ(j["paths"].size(), 6u);
  EXPECT_EQ(j["paths"][0]["name"], "TRIlong");
  EXPECT_EQ(j["paths"][0]["points"], 5);
  EXPECT_EQ(j["paths"][0]["wrap_objects"].size(), 3u);
  EXPECT_EQ(j["paths_not_computed"].size(), 0u);
}

TEST_F(Inspect, FunctionBasedPathsAreListedWithTheirCoordinatesAndFunctions) {
  const std::string model = std::string(SINEW_TEST_DATA_DIR) + "/sinew/function_based_paths.osim";
  const CliRun run = Run("inspect " + model);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("paths (2):"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("  spring  FunctionBasedPath of q1, q2 (length "
                         "MultivariatePolynomialFunction; no points: not drawn)\n"),
            std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("  act  FunctionBasedPath of q1 (length PolynomialFunction, moment arm "
                         "functions, lengthening speed function; no points: not drawn)\n"),
            std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("path parts not computed (0):"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("not simulated (0):"), std::string::npos) << run.out;
  const CliRun json = Run("inspect --json " + model);
  ASSERT_EQ(json.exit_code, 0) << json.err;
  const nlohmann::json j = nlohmann::json::parse(json.out);
  ASSERT_EQ(j["paths"].size(), 2u);
  EXPECT_EQ(j["paths"][0]["type"], "FunctionBasedPath");
  EXPECT_EQ(j["paths"][0]["coordinates"], nlohmann::json({"q1", "q2"}));
}

TEST_F(Inspect, JsonFields) {
  const CliRun run = Run("inspect --json " + kArm26);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json j = nlohmann::json::parse(run.out);
  EXPECT_EQ(j["version"], 40000);
  ASSERT_EQ(j["bodies"].size(), 3u);  // ground is not listed
  for (const auto& b : j["bodies"]) EXPECT_NE(b["name"], "ground");
  EXPECT_EQ(j["bodies"][1]["name"], "r_humerus");
  EXPECT_NEAR(j["bodies"][1]["mass"].get<double>(), 1.8645719999999999, 1e-15);
  ASSERT_EQ(j["joints"].size(), 3u);
  EXPECT_EQ(j["joints"][0]["name"], "offset");
  EXPECT_EQ(j["joints"][0]["type"], "WeldJoint");
  EXPECT_EQ(j["joints"][0]["parent"], "ground");  // offset frames resolved to bodies
  EXPECT_EQ(j["joints"][0]["child"], "base");
  EXPECT_EQ(j["joints"][2]["coordinates"][0], "r_elbow_flex");
  ASSERT_EQ(j["coordinates"].size(), 2u);
  EXPECT_EQ(j["coordinates"][0]["name"], "r_shoulder_elev");
  EXPECT_TRUE(j["coordinates"][0]["default_value"].is_number());
  EXPECT_TRUE(j["coordinates"][0]["default_speed_value"].is_number());
  EXPECT_EQ(j["coordinates"][0]["locked"], false);
  ASSERT_EQ(j["forces"].size(), 6u);
  EXPECT_EQ(j["forces"][0]["name"], "TRIlong");
  EXPECT_EQ(j["forces"][0]["type"], "Thelen2003Muscle");
  EXPECT_TRUE(j["constraints"].is_array());
  ASSERT_EQ(j["markers"].size(), 3u);
  EXPECT_EQ(j["markers"][0]["body"], "base");
  EXPECT_TRUE(j["warnings"].is_array());
  EXPECT_EQ(j["not_simulated"].size(), 0u);  // muscles and wrap objects are all simulated
}

TEST_F(Inspect, BadInputExitsWithTwo) {
  const std::string file = Path("bad_inspect.osim");
  std::ofstream(file) << "<OpenSimDocument Version=\"40000\">\n<Model name=\"m\">\n"
                         "<BodySet><objects><Body name=\"b\"><mass>x</mass></Body>\n";
  const CliRun run = Run("inspect " + file);
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("sinew: error: " + file + ":"), std::string::npos) << run.err;
  const CliRun missing = Run("inspect " + Path("nonexistent/model.osim"));
  EXPECT_EQ(missing.exit_code, 2) << missing.err;
  EXPECT_NE(missing.err.find("sinew: error: " + Path("nonexistent/model.osim")), std::string::npos)
      << missing.err;
}

TEST_F(Inspect, InvalidUtf8InANameIsEscapedInJson) {
  std::string model = testing::ReadText(kArm26);
  const std::string from = "<Model name=\"arm26\">";
  ASSERT_NE(model.find(from), std::string::npos);
  model.replace(model.find(from), from.size(), "<Model name=\"ar\xFF\xFEm26\">");
  std::ofstream(Path("bytes.osim"), std::ios::binary) << model;
  const CliRun run = Run("inspect --json " + Path("bytes.osim"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json j = nlohmann::json::parse(run.out);  // valid UTF-8 JSON
  EXPECT_EQ(j["name"], "ar\uFFFD\uFFFDm26");
}

}  // namespace
}  // namespace sinew

// The .glb files Sinew writes pass the Khronos glTF validator (npm gltf-validator, pinned in
// web/package.json) with no errors and no warnings: a reference independent of our writer and
// of our own parsing in glb_test_util.h. Skipped when node or the validator is not installed.
#include <gtest/gtest.h>
#include <sinew/io/osim_reader.h>
#include <sinew/io/storage.h>
#include <sinew/viz/gltf_writer.h>
#include <sinew/viz/motion_poses.h>
#include <sinew/viz/path_lines.h>
#include <sinew/viz/view_hints.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "viz/two_link_spec.h"

namespace sinew::viz {
namespace {

namespace fs = std::filesystem;

TEST(GltfValidatorTest, KhronosValidatorFindsNoIssues) {
  const fs::path web = fs::path(SINEW_TEST_DATA_DIR) / ".." / ".." / "web";
  if (std::system("command -v node >/dev/null 2>&1") != 0 ||
      !fs::exists(web / "node_modules" / "gltf-validator")) {
    GTEST_SKIP() << "node or web/node_modules/gltf-validator missing (run scripts/setup.sh)";
  }
  const fs::path dir =
      fs::temp_directory_path() / ("sinew_gltf_validator_" + std::to_string(getpid()));
  fs::create_directories(dir);
  // A small animated scene, the same without motion, one with no geometry at all, and the
  // full Rajagopal2016 model with 81 meshes and the 599-frame running motion.
  VisualOptions mesh;
  mesh.geometry_dirs = {testing::kDataDir + "/opensim-org/opensim-models/Geometry"};
  VisualOptions none;
  none.mode = VisType::kNone;
  const model::ModelSpec two_link = testing::TwoLinkSpec();
  const model::ModelSpec rajagopal = io::ReadOsim(
      testing::kDataDir + "/opensim-org/opensim-models/Models/Rajagopal/Rajagopal2016.osim");
  const BodyMotion running = MotionFromTable(
      rajagopal,
      io::ReadStorage(testing::kDataDir + "/opensim-org/opensim-models/Pipelines/Hamner/"
                                          "outputReference/ResultsIK/subject02_running_ik.mot"),
      nullptr);
  // arm26's muscles as lines over its wrap surfaces, one line mesh per frame.
  const model::ModelSpec arm26 =
      io::ReadOsim(testing::kDataDir + "/opensim-org/opensim-models/Models/Arm26/arm26.osim");
  io::Storage elbow;
  elbow.labels = {"r_elbow_flex"};
  elbow.time = {0.0, 0.5, 1.0};
  elbow.values = {0.0, 1.2, 2.2};
  const BodyMotion flexing = MotionFromTable(arm26, elbow, nullptr);
  const PathLines arm26_lines = CalcPathLines(arm26, flexing, nullptr);
  PathLines shaded_lines = arm26_lines;  // with per-vertex colours (COLOR_0)
  io::Storage activation;
  activation.labels = {"/forceset/BIClong/activation"};
  activation.time = {0.0, 1.0};
  activation.values = {0.1, 0.9};
  ShadeByActivation(activation, flexing.times, shaded_lines);
  // The viewer's hints with a contact arrow that appears, turns and vanishes (scale 0).
  ViewHints hints = MakeViewHints(two_link, BuildVisualScene(two_link, mesh),
                                  testing::SwingMotion(3, 0, 0.1, 0.3), ModelFloor(two_link));
  hints.arrows.names = {"contact.link"};
  hints.arrows.bodies = {1};
  hints.arrows.start.assign(3, {Vec3(0.1, 0, 0)});
  hints.arrows.force = {{Vec3::Zero()}, {Vec3(0, 10, 0)}, {Vec3(3, -4, 0)}};
  hints.arrows.body_weight = 10;
  hints.arrows.unit_length = 0.5;
  hints.arrows.metres_per_newton = 0.05;
  const BodyMotion still = DefaultPoseMotion(arm26);
  const PathLines still_lines = CalcPathLines(arm26, still, nullptr);
  const std::vector<std::pair<std::string, std::vector<uint8_t>>> files = {
      {"arm26_paths.glb", WriteGlb(BuildVisualScene(arm26, none), flexing, "p", &arm26_lines)},
      {"arm26_shaded.glb", WriteGlb(BuildVisualScene(arm26, none), flexing, "h", &shaded_lines)},
      {"arm26_still.glb", WriteGlb(BuildVisualScene(arm26, none), still, "q", &still_lines)},
      {"animated.glb",
       WriteGlb(BuildVisualScene(two_link, mesh), testing::SwingMotion(5, 0, 0.1, 0.3), "a")},
      {"static.glb", WriteGlb(BuildVisualScene(two_link, mesh), {}, "s")},
      {"arrows.glb", WriteGlb(BuildVisualScene(two_link, mesh),
                              testing::SwingMotion(3, 0, 0.1, 0.3), "c", nullptr, &hints)},
      {"empty.glb", WriteGlb(BuildVisualScene(two_link, none), {}, "e")},
      {"rajagopal.glb", WriteGlb(BuildVisualScene(rajagopal, mesh), running, "r")}};
  std::string args;
  for (const auto& [name, bytes] : files) {
    WriteFileBytes((dir / name).string(), bytes);
    args += " " + (dir / name).string();
  }
  const fs::path report = dir / "report.jsonl";
  const std::string command =
      "cd " + web.string() + " && node validate_gltf.mjs" + args + " >" + report.string() + " 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  std::ifstream in(report);
  std::string line;
  int checked = 0;
  while (std::getline(in, line)) {
    const nlohmann::json r = nlohmann::json::parse(line);
    EXPECT_EQ(r["errors"], 0) << r.dump(1);
    EXPECT_EQ(r["warnings"], 0) << r.dump(1);
    ++checked;
  }
  EXPECT_EQ(checked, static_cast<int>(files.size()));
  if (!HasFailure()) fs::remove_all(dir);
}

}  // namespace
}  // namespace sinew::viz

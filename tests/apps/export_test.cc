// `sinew export` and `sinew render` on a real model: Rajagopal2016 with all 81 of its .vtp
// meshes, driven by the Hamner running IK motion (same coordinate names). The .glb is read back
// and checked against the model file and the motion table.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include <sinew/io/mesh_file.h>
#include <sinew/io/storage.h>
#include "viz/glb_test_util.h"
#include <sinew/viz/image.h>

namespace sinew {
namespace {

namespace fs = std::filesystem;

const std::string kData = SINEW_TEST_DATA_DIR;
const std::string kModel = kData + "/opensim-org/opensim-models/Models/Rajagopal/Rajagopal2016.osim";
const std::string kGeometry = kData + "/opensim-org/opensim-models/Geometry";
const std::string kMotion = kData + "/opensim-org/opensim-models/Pipelines/Hamner/outputReference/ResultsIK/subject02_running_ik.mot";

struct CliRun {
  int code = -1;
  std::string out, err;
};

// Runs the sinew program with `args` (no mesh folders from the environment).
CliRun Sinew(const std::string& args, const fs::path& dir) {
  const fs::path out = dir / "stdout.txt", err = dir / "stderr.txt";
  const std::string command = "env -u SINEW_GEOMETRY_PATH " + std::string(SINEW_CLI_PATH) + " " +
                              args + " >" + out.string() + " 2>" + err.string();
  CliRun run;
  const int status = std::system(command.c_str());
  run.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  auto slurp = [](const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  };
  run.out = slurp(out);
  run.err = slurp(err);
  return run;
}

int CountOccurrences(const std::string& text, const std::string& needle) {
  int n = 0;
  for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
  return n;
}

class ExportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("sinew_export_test_" + std::to_string(getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    std::ifstream in(kModel);
    std::stringstream s;
    s << in.rdbuf();
    model_text_ = s.str();
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(dir_);
  }
  fs::path dir_;
  std::string model_text_;
};

TEST_F(ExportTest, RajagopalGlbHasEveryMeshAndTheMotion) {
  const fs::path glb_file = dir_ / "rajagopal.glb";
  CliRun run = Sinew("export " + kModel + " --motion " + kMotion + " --vis mesh --geometry-dir " +
                         kGeometry + " --out " + glb_file.string(),
                     dir_);
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(run.err.find("warning"), std::string::npos) << run.err;
  viz::testing::ParsedGlb glb = viz::testing::ParseGlb(viz::ReadFileBytes(glb_file.string()));
  const auto& doc = glb.doc;
  // Counted in the model file: one <Mesh> per attached mesh, <Body> per body (+ ground).
  const int n_meshes = CountOccurrences(model_text_, "<Mesh ");
  const int n_bodies = CountOccurrences(model_text_, "<Body ") + 1;
  EXPECT_EQ(n_meshes, 81);
  EXPECT_EQ(n_bodies, 23);
  EXPECT_EQ(static_cast<int>(doc["meshes"].size()), n_meshes);
  EXPECT_EQ(static_cast<int>(doc["nodes"].size()), 1 + n_bodies + n_meshes);
  // Every mesh node names the .vtp it came from, and the triangles match that file's.
  const std::vector<std::string> dirs = io::MeshSearchDirs(kModel, {kGeometry});
  int mesh_nodes = 0;
  for (const auto& node : doc["nodes"]) {
    if (!node.contains("mesh")) continue;
    ++mesh_nodes;
    const std::string source = node["extras"]["source"];
    ASSERT_EQ(fs::path(source).extension(), ".vtp") << source;
    std::optional<std::string> path = io::FindMeshFile(source, dirs);
    ASSERT_TRUE(path) << source;
    const auto& primitive = doc["meshes"][node["mesh"].get<int>()]["primitives"][0];
    const int indices = doc["accessors"][primitive["indices"].get<int>()]["count"];
    EXPECT_EQ(static_cast<size_t>(indices), 3 * io::ReadMesh(*path).triangles.size()) << source;
  }
  EXPECT_EQ(mesh_nodes, n_meshes);
  // The animation has one key per motion row, times from 0.
  const io::Storage motion = io::ReadStorage(kMotion);
  ASSERT_EQ(doc["animations"].size(), 1u);
  const auto& anim = doc["animations"][0];
  EXPECT_EQ(static_cast<int>(anim["channels"].size()), 2 * n_bodies);
  // The pelvis hangs from ground by a CustomJoint with identity offsets: its translation is
  // (pelvis_tx, ty, tz) and its rotation Rz(tilt) Rx(list) Ry(rotation), angles in degrees.
  int pelvis_node = -1;
  for (size_t i = 0; i < doc["nodes"].size(); ++i) {
    if (doc["nodes"][i]["name"] == "pelvis") pelvis_node = static_cast<int>(i);
  }
  ASSERT_GE(pelvis_node, 0);
  const double deg = M_PI / 180;
  for (const auto& channel : anim["channels"]) {
    if (channel["target"]["node"] != pelvis_node) continue;
    const auto& sampler = anim["samplers"][channel["sampler"].get<int>()];
    std::vector<float> times = viz::testing::ReadFloatAccessor(glb, sampler["input"]);
    ASSERT_EQ(static_cast<int>(times.size()), motion.NumRows());
    EXPECT_EQ(times[0], 0.0f);
    std::vector<float> out = viz::testing::ReadFloatAccessor(glb, sampler["output"]);
    for (int row : {0, 250, motion.NumRows() - 1}) {
      auto col = [&](const char* label) { return motion.Value(row, motion.FindColumn(label)); };
      EXPECT_NEAR(times[row], motion.time[row] - motion.time[0], 1e-5);
      if (channel["target"]["path"] == "translation") {
        EXPECT_NEAR(out[3 * row], col("pelvis_tx"), 1e-6);
        EXPECT_NEAR(out[3 * row + 1], col("pelvis_ty"), 1e-6);
        EXPECT_NEAR(out[3 * row + 2], col("pelvis_tz"), 1e-6);
      } else {
        const Eigen::Quaterniond expected =
            Eigen::AngleAxisd(col("pelvis_tilt") * deg, Eigen::Vector3d::UnitZ()) *
            Eigen::AngleAxisd(col("pelvis_list") * deg, Eigen::Vector3d::UnitX()) *
            Eigen::AngleAxisd(col("pelvis_rotation") * deg, Eigen::Vector3d::UnitY());
        const Eigen::Quaterniond got(out[4 * row + 3], out[4 * row], out[4 * row + 1],
                                     out[4 * row + 2]);
        // Single-precision storage: angle between them within a few 1e-7 rad.
        EXPECT_LT(got.angularDistance(expected), 1e-6) << "row " << row;
      }
    }
  }
}

TEST_F(ExportTest, MissingMeshesWarnAndFallBackToPrimitives) {
  // Without the shared Geometry folder only the model's own 9 meshes are found.
  const fs::path glb_file = dir_ / "partial.glb";
  CliRun run = Sinew("export " + kModel + " --vis mesh --out " + glb_file.string(), dir_);
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(CountOccurrences(run.err, "warning"), 72) << run.err;
  EXPECT_NE(run.err.find("mesh file 'r_patella.vtp' not found in: "), std::string::npos);
  EXPECT_NE(run.err.find("Rajagopal/Geometry"), std::string::npos);
  viz::testing::ParsedGlb glb = viz::testing::ParseGlb(viz::ReadFileBytes(glb_file.string()));
  int vtp = 0, primitive = 0;
  for (const auto& node : glb.doc["nodes"]) {
    if (!node.contains("extras") || !node["extras"].contains("source")) continue;
    const std::string source = node["extras"]["source"];
    (source == "primitive" ? primitive : vtp) += 1;
  }
  EXPECT_EQ(vtp, 9);
  EXPECT_GT(primitive, 0);
}

TEST_F(ExportTest, HtmlViewerAndRenderedImage) {
  const fs::path html = dir_ / "rajagopal.html", png = dir_ / "rajagopal.png";
  CliRun run = Sinew("export " + kModel + " --vis primitives --out " + html.string(), dir_);
  ASSERT_EQ(run.code, 0) << run.err;
  std::ifstream in(html);
  std::stringstream page;
  page << in.rdbuf();
  EXPECT_NE(page.str().find("<script type=\"importmap\">{\"imports\""), std::string::npos);
  EXPECT_GT(page.str().size(), 500000u);  // three.js is inside
  run =
      Sinew("render " + kModel + " --motion " + kMotion + " --time 0.5 --vis mesh --geometry-dir " +
                kGeometry + " --width 200 --height 240 --out " + png.string(),
            dir_);
  ASSERT_EQ(run.code, 0) << run.err;
  viz::Image image = viz::DecodePng(viz::ReadFileBytes(png.string()), png.string());
  EXPECT_EQ(image.width, 200);
  EXPECT_EQ(image.height, 240);
  int drawn = 0;
  for (size_t i = 0; i < image.rgb.size(); i += 3) drawn += image.rgb[i] != 245;
  EXPECT_GT(drawn, 1000) << "the skeleton covers some of the picture";
}

class StatesExportTest : public ExportTest, public ::testing::WithParamInterface<bool> {};

TEST_P(StatesExportTest, StatesFileDrivesThePendulumAsHandComputed) {
  // SinglePin (OpenSim 3 format): rod1 hangs from a z pin at the ground origin with its body
  // frame 0.5 m below the pin, so at angle q its origin is (0.5 sin q, -0.5 cos q, 0) and its
  // rotation is q about z. The states file is OpenSim's own 3 s passive simulation.
  const std::string model =
      kData + "/opensim-org/opensim-core/Applications/Analyze/tests/resources/SinglePin.osim";
  // Also as a simulation writes states: OpenSim 4 labels (/jointset/pin1/r1_z/value).
  const bool opensim4_labels = GetParam();
  std::string states = kData +
                       "/opensim-org/opensim-core/Applications/Analyze/tests/resources/"
                       "SinglePin_states.sto";
  if (opensim4_labels) {
    io::Storage relabelled = io::ReadStorage(states);
    for (std::string& label : relabelled.labels) {
      label = "/jointset/pin1/r1_z/" + std::string(label == "r1_z" ? "value" : "speed");
    }
    states = (dir_ / "states.sto").string();
    io::WriteStorage(relabelled, states);
  }
  const fs::path glb_file = dir_ / "pin.glb";
  CliRun run = Sinew(
      "export " + model + " --states " + states + " --vis primitives --out " + glb_file.string(),
      dir_);
  ASSERT_EQ(run.code, 0) << run.err;
  viz::testing::ParsedGlb glb = viz::testing::ParseGlb(viz::ReadFileBytes(glb_file.string()));
  const io::Storage table = io::ReadStorage(states);
  const int q_column = table.FindColumn(opensim4_labels ? "/jointset/pin1/r1_z/value" : "r1_z");
  ASSERT_GE(q_column, 0);
  const auto& doc = glb.doc;
  int rod = -1;
  for (size_t i = 0; i < doc["nodes"].size(); ++i) {
    if (doc["nodes"][i]["name"] == "rod1") rod = static_cast<int>(i);
  }
  ASSERT_GE(rod, 0);
  int checked = 0;
  const auto& anim = doc["animations"][0];
  for (const auto& channel : anim["channels"]) {
    if (channel["target"]["node"] != rod) continue;
    const auto& sampler = anim["samplers"][channel["sampler"].get<int>()];
    const std::vector<float> out = viz::testing::ReadFloatAccessor(glb, sampler["output"]);
    for (int row = 0; row < table.NumRows(); ++row) {
      const double q = table.Value(row, q_column);
      if (channel["target"]["path"] == "translation") {
        ASSERT_NEAR(out[3 * row], 0.5 * std::sin(q), 1e-6) << "row " << row;
        ASSERT_NEAR(out[3 * row + 1], -0.5 * std::cos(q), 1e-6) << "row " << row;
        ASSERT_NEAR(out[3 * row + 2], 0.0, 1e-6);
      } else {
        // Quaternion of a rotation q about z, up to sign: (0, 0, sin(q/2), cos(q/2)).
        const double s = std::sin(q / 2), c = std::cos(q / 2);
        const double dot = out[4 * row + 2] * s + out[4 * row + 3] * c;
        ASSERT_NEAR(std::abs(dot), 1.0, 1e-6) << "row " << row;
      }
      ++checked;
    }
  }
  EXPECT_EQ(checked, 2 * table.NumRows());
}

INSTANTIATE_TEST_SUITE_P(Labels, StatesExportTest, ::testing::Bool());

TEST_F(ExportTest, BadInputExitsWithCodeTwo) {
  CliRun run = Sinew("export " + kData + "/nothing.osim --out " + (dir_ / "x.glb").string(), dir_);
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find("nothing.osim"), std::string::npos) << run.err;
  run = Sinew("export " + kModel + " --vis primitives --out " + (dir_ / "x.obj").string(), dir_);
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find(".glb or .html"), std::string::npos) << run.err;
  run = Sinew("render " + kModel + " --vis primitives --time 1 --out " + (dir_ / "x.png").string(),
              dir_);
  EXPECT_EQ(run.code, 2);
  run = Sinew("render " + kModel + " --motion " + kMotion + " --time 99 --vis primitives --out " +
                  (dir_ / "x.png").string(),
              dir_);
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find("outside"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace sinew

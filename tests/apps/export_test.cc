// `sinew export` and `sinew render` on a real model: Rajagopal2016 with all 81 of its .vtp
// meshes, driven by the Hamner running IK motion (same coordinate names). The .glb is read back
// and checked against the model file and the motion table.
#include <gtest/gtest.h>
#include <sinew/io/mesh_file.h>
#include <sinew/io/storage.h>
#include <sinew/viz/image.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <pugixml.hpp>
#include <string>
#include <vector>

#include "apps/cli_test_util.h"
#include "viz/glb_test_util.h"

namespace sinew {
namespace {

namespace fs = std::filesystem;

const std::string kData = SINEW_TEST_DATA_DIR;
const std::string kModel =
    kData + "/opensim-org/opensim-models/Models/Rajagopal/Rajagopal2016.osim";
const std::string kGeometry = kData + "/opensim-org/opensim-models/Geometry";
const std::string kMotion = kData +
                            "/opensim-org/opensim-models/Pipelines/Hamner/outputReference/"
                            "ResultsIK/subject02_running_ik.mot";

using testing::CliRun;
using testing::CountOccurrences;

class ExportTest : public testing::CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    model_text_ = testing::ReadText(kModel);
  }
  std::string model_text_;
};

// The mesh files the model names that are neither beside it nor in its Geometry/ folder (the
// folders searched when no other is given): by an XML parser and the file system, not Sinew.
struct MissingMeshes {
  std::vector<std::string> files;  ///< each once, in model order
  int geometries = 0;              ///< the <Mesh> elements that name one of them
};

MissingMeshes MeshesNotBesideTheModel() {
  pugi::xml_document doc;
  EXPECT_TRUE(doc.load_file(kModel.c_str()));
  const fs::path folder = fs::path(kModel).parent_path();
  MissingMeshes missing;
  for (const pugi::xpath_node& n : doc.select_nodes("//BodySet//Mesh/mesh_file")) {
    const std::string file = n.node().text().as_string();
    if (fs::exists(folder / file) || fs::exists(folder / "Geometry" / file)) continue;
    ++missing.geometries;
    std::vector<std::string>& files = missing.files;
    if (std::find(files.begin(), files.end(), file) == files.end()) files.push_back(file);
  }
  return missing;
}

TEST_F(ExportTest, RajagopalGlbHasEveryMeshAndTheMotion) {
  const fs::path glb_file = dir() / "rajagopal.glb";
  CliRun run = Run("export " + kModel + " --motion " + kMotion + " --vis mesh --geometry-dir " +
                   kGeometry + " --out " + glb_file.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.err.find("warning"), std::string::npos) << run.err;
  viz::testing::ParsedGlb glb = viz::testing::ParseGlb(viz::ReadFileBytes(glb_file.string()));
  const auto& doc = glb.doc;
  // Counted in the model file: one <Mesh> per attached mesh, <Body> per body (+ ground).
  const int n_meshes = CountOccurrences(model_text_, "<Mesh ");
  const int n_bodies = CountOccurrences(model_text_, "<Body ") + 1;
  EXPECT_EQ(n_meshes, 81);
  EXPECT_EQ(n_bodies, 23);
  // Besides: a node "paths" naming every <GeometryPath> of the ForceSet (80; the <defaults>
  // hold one more), with one child and one line
  // mesh per motion row (docs: one line mesh per frame, shown in turn).
  const int n_paths =
      CountOccurrences(model_text_.substr(model_text_.find("<ForceSet")), "<GeometryPath");
  EXPECT_EQ(n_paths, 80);
  const int n_rows = io::ReadStorage(kMotion).NumRows();
  EXPECT_EQ(static_cast<int>(doc["meshes"].size()), n_meshes + n_rows);
  EXPECT_EQ(static_cast<int>(doc["nodes"].size()), 1 + n_bodies + n_meshes + 1 + n_rows);
  for (const auto& node : doc["nodes"]) {
    if (node["name"] == "paths") {
      EXPECT_EQ(static_cast<int>(node["extras"]["paths"].size()), n_paths);
    }
  }
  // Every mesh node names the .vtp it came from, and the triangles match that file's.
  const std::vector<std::string> dirs = io::MeshSearchDirs(kModel, {kGeometry});
  int mesh_nodes = 0;
  for (const auto& node : doc["nodes"]) {
    if (!node.contains("mesh") || node["name"].get<std::string>().starts_with("paths@")) continue;
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
  EXPECT_EQ(static_cast<int>(anim["channels"].size()), 2 * n_bodies + n_rows);
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

// The patellae hang on the femurs by patellofemoral joints whose coordinates the IK motion does
// not hold (knee_angle_r_beta is not a column): only the CoordinateCouplerConstraints move them,
// with the knee. Without the couplers the patella would keep one pose relative to the femur.
TEST_F(ExportTest, HamnerRunningMovesThePatellaeWithTheKnees) {
  const fs::path glb_file = dir() / "running.glb";
  CliRun run = Run("export " + kModel + " --motion " + kMotion + " --vis primitives --out " +
                   glb_file.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  viz::testing::ParsedGlb glb = viz::testing::ParseGlb(viz::ReadFileBytes(glb_file.string()));
  const auto& doc = glb.doc;
  const io::Storage motion = io::ReadStorage(kMotion);
  ASSERT_LT(motion.FindColumn("knee_angle_r_beta"), 0);
  // The rows of the straightest and the most bent right knee.
  const int knee = motion.FindColumn("knee_angle_r");
  int straight = 0, bent = 0;
  for (int row = 0; row < motion.NumRows(); ++row) {
    if (motion.Value(row, knee) < motion.Value(straight, knee)) straight = row;
    if (motion.Value(row, knee) > motion.Value(bent, knee)) bent = row;
  }
  ASSERT_GT(motion.Value(bent, knee) - motion.Value(straight, knee), 60.0);  // degrees
  // Each body's rotation key at a row, from its rotation channel.
  auto rotation = [&](const std::string& body, int row) {
    for (const auto& channel : doc["animations"][0]["channels"]) {
      const auto& node = doc["nodes"][channel["target"]["node"].get<int>()];
      if (node["name"] != body || channel["target"]["path"] != "rotation") continue;
      const auto& sampler = doc["animations"][0]["samplers"][channel["sampler"].get<int>()];
      const std::vector<float> out = viz::testing::ReadFloatAccessor(glb, sampler["output"]);
      return Eigen::Quaterniond(out[4 * row + 3], out[4 * row], out[4 * row + 1], out[4 * row + 2]);
    }
    ADD_FAILURE() << "no rotation channel for " << body;
    return Eigen::Quaterniond::Identity();
  };
  const Eigen::Quaterniond straight_rel =
      rotation("femur_r", straight).inverse() * rotation("patella_r", straight);
  const Eigen::Quaterniond bent_rel =
      rotation("femur_r", bent).inverse() * rotation("patella_r", bent);
  const double turn = straight_rel.angularDistance(bent_rel);
  EXPECT_GT(turn, 0.1) << "the patella did not turn on the femur";
  std::cout << "patella_r turned " << turn << " rad on the femur between knee angles "
            << motion.Value(straight, knee) << " and " << motion.Value(bent, knee) << " deg\n";
}

TEST_F(ExportTest, MissingMeshesAreSummarizedInOneLineAndListedWithVerbose) {
  // Without the shared Geometry folder only the model's own meshes are found.
  const MissingMeshes missing_meshes = MeshesNotBesideTheModel();
  const std::vector<std::string>& missing = missing_meshes.files;
  ASSERT_GT(missing.size(), 3u);
  const fs::path glb_file = dir() / "partial.glb";
  CliRun run = Run("export " + kModel + " --vis mesh --out " + glb_file.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(CountOccurrences(run.err, "sinew: warning:"), 1) << run.err;
  const std::string summary = "sinew: warning: " + std::to_string(missing.size()) +
                              " mesh files were not found (" + missing[0] + ", " + missing[1] +
                              ", " + missing[2] + " and " + std::to_string(missing.size() - 3) +
                              " more); their bodies are drawn as primitives. Searched: ";
  EXPECT_NE(run.err.find(summary), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("Rajagopal/Geometry"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find(". Add the folder that holds them with --geometry-dir DIR or "
                         "$SINEW_GEOMETRY_PATH; --verbose lists every one\n"),
            std::string::npos)
      << run.err;
  viz::testing::ParsedGlb glb = viz::testing::ParseGlb(viz::ReadFileBytes(glb_file.string()));
  int vtp = 0, primitive = 0;
  for (const auto& node : glb.doc["nodes"]) {
    if (!node.contains("extras") || !node["extras"].contains("source")) continue;
    const std::string source = node["extras"]["source"];
    (source == "primitive" ? primitive : vtp) += 1;
  }
  // Every <Mesh> of the model whose file was found is drawn from it.
  EXPECT_EQ(vtp, CountOccurrences(model_text_, "<Mesh ") - missing_meshes.geometries);
  EXPECT_GT(primitive, 0);
  // --verbose: one line per geometry whose file is missing, then the summary.
  run = Run("export " + kModel + " --vis mesh --verbose --out " + glb_file.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (const std::string& file : missing) {
    EXPECT_NE(run.err.find("mesh file '" + file + "' not found in: "), std::string::npos) << file;
  }
  EXPECT_EQ(CountOccurrences(run.err, "sinew: warning:"), missing_meshes.geometries + 1) << run.err;
  EXPECT_NE(run.err.find(summary), std::string::npos) << run.err;
  EXPECT_EQ(run.err.find("--verbose lists every one"), std::string::npos) << run.err;
  // render prints the same summary.
  run = Run("render " + kModel + " --vis mesh --width 40 --height 40 --out " +
            (dir() / "partial.png").string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(CountOccurrences(run.err, "sinew: warning:"), 1) << run.err;
  EXPECT_NE(run.err.find(summary), std::string::npos) << run.err;
}

TEST_F(ExportTest, HtmlViewerAndRenderedImage) {
  const fs::path html = dir() / "rajagopal.html", png = dir() / "rajagopal.png";
  CliRun run = Run("export " + kModel + " --vis primitives --out " + html.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string page = testing::ReadText(html);
  EXPECT_NE(page.find("<script type=\"importmap\">{\"imports\""), std::string::npos);
  EXPECT_GT(page.size(), 500000u);  // three.js is inside
  run = Run("render " + kModel + " --motion " + kMotion + " --time 0.5 --vis mesh --geometry-dir " +
            kGeometry + " --width 200 --height 240 --out " + png.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
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
    states = (dir() / "states.sto").string();
    io::WriteStorage(relabelled, states);
  }
  const fs::path glb_file = dir() / "pin.glb";
  CliRun run = Run("export " + model + " --states " + states + " --vis primitives --out " +
                   glb_file.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
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

TEST_F(ExportTest, RenderCreatesItsFolderAndWritesOnlyPng) {
  // Folders that do not exist yet, parents too; the extension in any case.
  const fs::path png = dir() / "new" / "deeper" / "pose.PNG";
  CliRun run =
      Run("render " + kModel + " --vis primitives --width 64 --height 48 --out " + png.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "wrote " + png.string() + " (64x48)\n");
  const viz::Image image = viz::DecodePng(viz::ReadFileBytes(png.string()), png.string());
  EXPECT_EQ(image.width, 64);
  EXPECT_EQ(image.height, 48);
  // Any other extension is refused before anything is written, naming the one supported.
  for (const std::string name : {"pose.jpg", "pose"}) {
    const fs::path out = dir() / "other" / name;
    run = Run("render " + kModel + " --vis primitives --out " + out.string());
    EXPECT_EQ(run.exit_code, 2) << name;
    const std::string ext = fs::path(name).extension().string();
    EXPECT_EQ(run.err, "sinew: error: " + out.string() +
                           ": the output is written as PNG only: its name must end in .png" +
                           (ext.empty() ? " (it has no extension)" : ", not " + ext) + "\n");
    EXPECT_FALSE(fs::exists(dir() / "other")) << name;
  }
  // export makes its folder too.
  const fs::path glb = dir() / "made" / "for" / "it.glb";
  run = Run("export " + kModel + " --vis primitives --out " + glb.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(fs::exists(glb));
}

// Pixels of muscle red (0.8, 0.1, 0.1), allowing for the edges blended with the background.
int RedPixels(const viz::Image& image) {
  int red = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const uint8_t* px = image.At(x, y);
      if (px[0] > 150 && px[1] < 120 && px[2] < 120 && px[0] > px[1] + 60) ++red;
    }
  }
  return red;
}

TEST_F(ExportTest, RenderDrawsArm26MusclesInRed) {
  const std::string arm26 = kData + "/opensim-org/opensim-models/Models/Arm26/arm26.osim";
  auto render = [&](const std::string& options) {
    const fs::path png = dir() / "arm26.png";
    const CliRun run =
        Run("render " + arm26 + " --width 120 --height 160 " + options + " --out " + png.string());
    EXPECT_EQ(run.exit_code, 0) << run.err;
    return viz::DecodePng(viz::ReadFileBytes(png.string()), png.string());
  };
  // With no body geometry the picture is the muscles alone: red lines on the background.
  const viz::Image lines = render("--vis none");
  const uint8_t* background = lines.At(0, 0);
  int red = 0, other = 0;
  for (int y = 0; y < lines.height; ++y) {
    for (int x = 0; x < lines.width; ++x) {
      const uint8_t* px = lines.At(x, y);
      if (std::equal(px, px + 3, background)) continue;
      (px[0] > px[1] && px[0] > px[2] ? red : other)++;
    }
  }
  EXPECT_GT(red, 200);
  EXPECT_EQ(other, 0);
  EXPECT_EQ(RedPixels(render("--vis none --no-paths")), 0);
  // Over the bones, the muscles add red pixels.
  EXPECT_GT(RedPixels(render("--vis primitives")),
            RedPixels(render("--vis primitives --no-paths")) + 100);
}

TEST_F(ExportTest, BadInputExitsWithCodeTwo) {
  CliRun run = Run("export " + kData + "/nothing.osim --out " + (dir() / "x.glb").string());
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("nothing.osim"), std::string::npos) << run.err;
  run = Run("export " + kModel + " --vis primitives --out " + (dir() / "x.obj").string());
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find(".glb or .html"), std::string::npos) << run.err;
  run = Run("render " + kModel + " --vis primitives --time 1 --out " + (dir() / "x.png").string());
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("sinew: error: --time needs --states or --motion\n"), std::string::npos)
      << run.err;
  run = Run("render " + kModel + " --motion " + kMotion + " --time 99 --vis primitives --out " +
            (dir() / "x.png").string());
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("outside"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace sinew

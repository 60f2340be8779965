// Muscle paths in the exported glTF: the lines of every frame are the paths that
// paths::GeometryPath::CalcState computes from coordinates set here (not from the motion's
// own), with the points along each wrapped arc; they show one frame at a time in the
// animation, and --no-paths (ExportOptions::paths) leaves them out.
#include <gtest/gtest.h>
#include <sinew/io/osim_reader.h>
#include <sinew/kinematics/forward_kinematics.h>
#include <sinew/kinematics/kinematic_tree.h>
#include <sinew/paths/path_set.h>
#include <sinew/viz/export_animation.h>
#include <sinew/viz/gltf_writer.h>
#include <sinew/viz/motion_poses.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>

#include "viz/glb_test_util.h"
#include "viz/two_link_spec.h"

namespace sinew::viz {
namespace {

namespace fs = std::filesystem;

const std::string kArm26 =
    testing::kDataDir + "/opensim-org/opensim-models/Models/Arm26/arm26.osim";
const std::string kTugOfWar =
    testing::kDataDir + "/MyoHub/myoconverter/models/osim/TugOfWar/tugofwar.osim";

// A motion table driving `columns` linearly from `from` to `to` over `rows` rows.
io::Storage Ramp(const std::vector<std::string>& columns, const std::vector<double>& from,
                 const std::vector<double>& to, int rows) {
  io::Storage table;
  table.labels = columns;
  for (int r = 0; r < rows; ++r) {
    const double s = static_cast<double>(r) / (rows - 1);
    table.time.push_back(0.5 + 0.1 * r);
    for (size_t c = 0; c < columns.size(); ++c) {
      table.values.push_back(from[c] + s * (to[c] - from[c]));
    }
  }
  return table;
}

// What a path should look like at row `row`: coordinates set by name over the defaults,
// poses from forward kinematics, the path from CalcState with arc points; the polyline is
// its points with each arc's interior points between the arc's two tangent points.
struct Expected {
  std::vector<std::vector<Vec3>> lines;
  int arc_points = 0;  // interior arc points over all paths
};

Expected ExpectedLines(const model::ModelSpec& spec, const io::Storage& table, int row) {
  kinematics::KinematicTree tree(spec);
  std::vector<double> q = tree.default_q();
  for (size_t c = 0; c < table.labels.size(); ++c) {
    for (size_t i = 0; i < spec.coordinates.size(); ++i) {
      if (spec.coordinates[i].name == table.labels[c]) q[i] = table.Value(row, static_cast<int>(c));
    }
  }
  std::vector<Transform> X_GB(tree.num_bodies());
  kinematics::CalcBodyPoses(tree, q, X_GB);
  Expected out;
  const paths::PathSet set(spec);
  paths::PathState state;
  for (const paths::GeometryPath& path : set.paths()) {
    path.CalcState(q, X_GB, state, true);
    std::vector<Vec3> line;
    for (const paths::PathPointState& point : state.points) {
      line.push_back(point.p_GP);
      if (point.wrap >= 0 && point.arc_length_to_next >= 0.0) {
        const std::vector<Vec3>& arc = state.arc_G[static_cast<size_t>(
            paths::PathState::ArcIndex(point.wrap, point.tangent))];
        for (size_t j = 1; j + 1 < arc.size(); ++j, ++out.arc_points) line.push_back(arc[j]);
      }
    }
    out.lines.push_back(line);
  }
  return out;
}

testing::ParsedGlb Export(const model::ModelSpec& spec, const BodyMotion& motion, bool paths,
                          const std::string& name) {
  const fs::path file =
      fs::temp_directory_path() / ("sinew_path_lines_" + std::to_string(getpid()) + name);
  ExportOptions options;
  options.visual.mode = VisType::kPrimitives;
  options.paths = paths;
  ExportAnimation(spec, motion, file.string(), options);
  std::ifstream in(file, std::ios::binary);
  const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                   std::istreambuf_iterator<char>());
  fs::remove(file);
  return testing::ParseGlb(bytes);
}

int NodeNamed(const nlohmann::json& doc, const std::string& name) {
  for (size_t i = 0; i < doc["nodes"].size(); ++i) {
    if (doc["nodes"][i].value("name", "") == name) return static_cast<int>(i);
  }
  return -1;
}

// Every frame's line mesh against the independent computation; counts the arc points seen.
void CheckLines(const std::string& model_file, const io::Storage& table, int* arc_points) {
  const model::ModelSpec spec = io::ReadOsim(model_file);
  const testing::ParsedGlb glb = Export(spec, MotionFromTable(spec, table, nullptr), true, ".glb");
  const nlohmann::json& doc = glb.doc;
  const int paths_node = NodeNamed(doc, "paths");
  EXPECT_GE(paths_node, 0);
  if (paths_node < 0) return;
  const paths::PathSet set(spec);
  std::vector<std::string> names;
  for (const paths::GeometryPath& path : set.paths()) names.push_back(path.component());
  EXPECT_EQ(doc["nodes"][paths_node]["extras"]["paths"].get<std::vector<std::string>>(), names);
  const auto& frames = doc["nodes"][paths_node]["children"];
  EXPECT_EQ(frames.size(), table.time.size());
  *arc_points = 0;
  for (int k = 0; k < table.NumRows() && k < static_cast<int>(frames.size()); ++k) {
    const Expected expected = ExpectedLines(spec, table, k);
    *arc_points += expected.arc_points;
    const auto& node = doc["nodes"][frames[k].get<int>()];
    const auto& mesh = doc["meshes"][node["mesh"].get<int>()];
    const auto counts = mesh["extras"]["vertex_counts"].get<std::vector<size_t>>();
    const auto& primitive = mesh["primitives"][0];
    EXPECT_EQ(primitive["mode"], 1);  // LINES
    const std::vector<float> positions =
        testing::ReadFloatAccessor(glb, primitive["attributes"]["POSITION"].get<int>());
    ASSERT_EQ(counts.size(), expected.lines.size());
    size_t v = 0;
    for (size_t i = 0; i < counts.size(); ++i) {
      ASSERT_EQ(counts[i], expected.lines[i].size()) << names[i] << " frame " << k;
      for (const Vec3& p : expected.lines[i]) {
        for (int c = 0; c < 3; ++c) {
          EXPECT_NEAR(positions[3 * v + c], p[c], 1e-6) << names[i] << " frame " << k;
        }
        ++v;
      }
    }
    EXPECT_EQ(positions.size(), 3 * v);
  }
  // The animation shows frame k's lines (scale 1) exactly from its time to the next frame's.
  const auto& animation = doc["animations"][0];
  std::map<int, int> sampler_of;
  for (const auto& channel : animation["channels"]) {
    if (channel["target"]["path"] == "scale") {
      sampler_of[channel["target"]["node"].get<int>()] = channel["sampler"].get<int>();
    }
  }
  for (int k = 0; k < static_cast<int>(frames.size()); ++k) {
    const auto& sampler = animation["samplers"][sampler_of.at(frames[k].get<int>())];
    EXPECT_EQ(sampler["interpolation"], "STEP");
    const std::vector<float> times = testing::ReadFloatAccessor(glb, sampler["input"].get<int>());
    const std::vector<float> scales = testing::ReadFloatAccessor(glb, sampler["output"].get<int>());
    for (size_t j = 0; j < times.size(); ++j) {
      const bool shown = std::abs(times[j] - (table.time[k] - table.time[0])) < 1e-6;
      EXPECT_EQ(scales[3 * j], shown ? 1.0f : 0.0f) << "frame " << k << " key " << j;
    }
  }
}

TEST(PathLinesTest, Arm26LinesAreItsWrappedPathsAtEveryFrame) {
  // Elbow from straight to flexed: the triceps wrap over the elbow's cylinder and the
  // ellipsoids.
  const io::Storage table = Ramp({"r_shoulder_elev", "r_elbow_flex"}, {0.0, 0.0}, {0.8, 2.2}, 7);
  int arc_points = 0;
  CheckLines(kArm26, table, &arc_points);
  EXPECT_GT(arc_points, 0) << "no wrapped arc was drawn";
}

TEST(PathLinesTest, TugOfWarStraightPathsAtEveryFrame) {
  const io::Storage table = Ramp({"block_tz"}, {-0.05}, {0.05}, 4);
  int arc_points = -1;
  CheckLines(kTugOfWar, table, &arc_points);
  EXPECT_EQ(arc_points, 0);
}

TEST(PathLinesTest, StaticPoseHasOneFrameOfLinesAndNoPathsLeavesThemOut) {
  const model::ModelSpec spec = io::ReadOsim(kArm26);
  const testing::ParsedGlb glb = Export(spec, DefaultPoseMotion(spec), true, "s.glb");
  const int paths_node = NodeNamed(glb.doc, "paths");
  ASSERT_GE(paths_node, 0);
  ASSERT_EQ(glb.doc["nodes"][paths_node]["children"].size(), 1u);
  EXPECT_FALSE(glb.doc.contains("animations"));
  const testing::ParsedGlb without = Export(spec, DefaultPoseMotion(spec), false, "n.glb");
  EXPECT_EQ(NodeNamed(without.doc, "paths"), -1);
  EXPECT_EQ(NodeNamed(without.doc, "paths@0"), -1);
}

}  // namespace
}  // namespace sinew::viz

namespace sinew::viz {
namespace {

// The colour PathColor should give: blue (0.15, 0.2, 0.75) at activation 0, muscle red
// (0.8, 0.1, 0.1) at 1, linear between.
Vec3 Shade(double a) { return (1 - a) * Vec3(0.15, 0.2, 0.75) + a * Vec3(0.8, 0.1, 0.1); }

TEST(PathLinesTest, ActivationsShadeTheLinesPerVertex) {
  const model::ModelSpec spec = io::ReadOsim(kArm26);
  // Coordinates and activations in one states table: BIClong in OpenSim 4's label, TRIlong in
  // the older one; the other muscles have none and stay red.
  io::Storage table;
  table.labels = {"/jointset/r_elbow/r_elbow_flex/value", "/forceset/BIClong/activation",
                  "TRIlong.activation"};
  table.time = {0.0, 1.0, 2.0};
  table.values = {0.2, 0.0, 1.0,  //
                  1.0, 0.5, 0.4,  //
                  1.5, 1.0, 0.0};
  const BodyMotion motion = MotionFromTable(spec, table, nullptr);
  PathLines lines = CalcPathLines(spec, motion, nullptr);
  // Frames at the rows' times, and one between rows: interpolated.
  EXPECT_EQ(ShadeByActivation(table, {0.0, 1.0, 2.0}, lines), 2);
  ASSERT_EQ(lines.activation.size(), 3u);
  const auto index = [&](const std::string& name) {
    return std::find(lines.names.begin(), lines.names.end(), name) - lines.names.begin();
  };
  const size_t bic = index("/forceset/BIClong"), tri = index("/forceset/TRIlong");
  const size_t bra = index("/forceset/BRA");
  ASSERT_LT(bra, lines.names.size());
  for (int k = 0; k < 3; ++k) {
    EXPECT_DOUBLE_EQ(lines.activation[k][bic], table.Value(k, 1));
    EXPECT_DOUBLE_EQ(lines.activation[k][tri], table.Value(k, 2));
    EXPECT_TRUE(std::isnan(lines.activation[k][bra]));
  }
  PathLines between = lines;
  ShadeByActivation(table, {0.5, 1.75, 2.0}, between);
  EXPECT_DOUBLE_EQ(between.activation[0][bic], 0.25);
  EXPECT_DOUBLE_EQ(between.activation[1][tri], 0.1);
  // In the .glb: every vertex of a path has its colour at that frame (COLOR_0, white material).
  VisualOptions none;
  none.mode = VisType::kNone;
  const testing::ParsedGlb glb =
      testing::ParseGlb(WriteGlb(BuildVisualScene(spec, none), motion, "shaded", &lines));
  const int paths_node = NodeNamed(glb.doc, "paths");
  ASSERT_GE(paths_node, 0);
  for (int k = 0; k < 3; ++k) {
    const int node = glb.doc["nodes"][paths_node]["children"][k].get<int>();
    const auto& mesh = glb.doc["meshes"][glb.doc["nodes"][node]["mesh"].get<int>()];
    const auto& primitive = mesh["primitives"][0];
    const auto& material = glb.doc["materials"][primitive["material"].get<int>()];
    EXPECT_EQ(material["pbrMetallicRoughness"]["baseColorFactor"],
              nlohmann::json({1.0, 1.0, 1.0, 1.0}));
    const std::vector<float> colors =
        testing::ReadFloatAccessor(glb, primitive["attributes"]["COLOR_0"].get<int>());
    const auto counts = mesh["extras"]["vertex_counts"].get<std::vector<size_t>>();
    size_t v = 0;
    for (size_t i = 0; i < counts.size(); ++i) {
      const Vec3 expected = i == bic   ? Shade(table.Value(k, 1))
                            : i == tri ? Shade(table.Value(k, 2))
                                       : Vec3(0.8, 0.1, 0.1);
      for (size_t j = 0; j < counts[i]; ++j, ++v) {
        for (int c = 0; c < 3; ++c) {
          EXPECT_NEAR(colors[3 * v + c], expected[c], 1e-6) << lines.names[i] << " frame " << k;
        }
      }
    }
    EXPECT_EQ(colors.size(), 3 * v);
  }
}

}  // namespace
}  // namespace sinew::viz

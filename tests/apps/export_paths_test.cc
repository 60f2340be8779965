// Muscle paths through the commands: `sinew simulate --export` draws them at the coordinates
// simulate wrote to states.sto (checked with paths::GeometryPath::CalcState), and `sinew
// render --states` shades them by the file's activations.
#include <gtest/gtest.h>
#include <sinew/io/osim_reader.h>
#include <sinew/io/storage.h>
#include <sinew/paths/path_set.h>
#include <sinew/viz/image.h>
#include <sinew/viz/motion_poses.h>

#include <fstream>
#include <string>
#include <vector>

#include "apps/cli_test_util.h"
#include "viz/glb_test_util.h"

namespace sinew {
namespace {

const std::string kArm26 =
    std::string(SINEW_TEST_DATA_DIR) + "/opensim-org/opensim-models/Models/Arm26/arm26.osim";

class SimulateExportPathsTest : public testing::CliTest {};

TEST_F(SimulateExportPathsTest, LinesAreThePathsAtTheSimulatedCoordinates) {
  const testing::CliRun run = Run("simulate " + kArm26 + " --duration 0.3 --vis primitives --out " +
                                  Path("sim") + " --export " + Path("sim.glb"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const viz::testing::ParsedGlb glb = viz::testing::ParseGlb(viz::ReadFileBytes(Path("sim.glb")));
  const nlohmann::json& doc = glb.doc;
  int paths_node = -1;
  for (size_t i = 0; i < doc["nodes"].size(); ++i) {
    if (doc["nodes"][i]["name"] == "paths") paths_node = static_cast<int>(i);
  }
  ASSERT_GE(paths_node, 0);
  const auto& frames = doc["nodes"][paths_node]["children"];
  // The states the run wrote, posed by forward kinematics (not by the engine).
  const model::ModelSpec spec = io::ReadOsim(kArm26);
  const io::Storage states = io::ReadStorage(Path("sim/states.sto"));
  const viz::BodyMotion motion = viz::MotionFromTable(spec, states, nullptr);
  ASSERT_EQ(frames.size(), motion.times.size());
  ASSERT_GE(motion.times.size(), 3u);
  const paths::PathSet set(spec);
  paths::PathState state;
  for (size_t k : {size_t{0}, motion.times.size() - 1}) {
    const auto& mesh = doc["meshes"][doc["nodes"][frames[k].get<int>()]["mesh"].get<int>()];
    const std::vector<float> positions = viz::testing::ReadFloatAccessor(
        glb, mesh["primitives"][0]["attributes"]["POSITION"].get<int>());
    size_t v = 0;
    for (const paths::GeometryPath& path : set.paths()) {
      path.CalcState(motion.q[k], motion.X_GB[k], state, true);
      std::vector<Vec3> line;
      for (const paths::PathPointState& point : state.points) {
        line.push_back(point.p_GP);
        if (point.wrap >= 0 && point.arc_length_to_next >= 0.0) {
          const std::vector<Vec3>& arc = state.arc_G[static_cast<size_t>(point.wrap)];
          if (arc.size() > 2) line.insert(line.end(), arc.begin() + 1, arc.end() - 1);
        }
      }
      for (const Vec3& p : line) {
        ASSERT_LE(3 * v + 2, positions.size());
        // states.sto keeps 9 or more digits; the engine's poses agree with forward kinematics.
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(positions[3 * v + c], p[c], 2e-6) << path.name();
        ++v;
      }
    }
    EXPECT_EQ(positions.size(), 3 * v);
  }
}

// Pixels whose colour is mostly red / mostly blue.
std::pair<int, int> RedAndBluePixels(const viz::Image& image) {
  int red = 0, blue = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const uint8_t* p = image.At(x, y);
      if (p[0] > 120 && p[0] > p[1] + 60 && p[0] > p[2] + 60) ++red;
      if (p[2] > 120 && p[2] > p[0] + 60 && p[2] > p[1] + 60) ++blue;
    }
  }
  return {red, blue};
}

TEST_F(SimulateExportPathsTest, FunctionBasedPathsAreLeftOutWithOneWarning) {
  // Two FunctionBasedPaths (tests/data/sinew/function_based_paths.osim): they simulate, and the
  // export says once, naming both, that they have no points to draw.
  const std::string model = std::string(SINEW_TEST_DATA_DIR) + "/sinew/function_based_paths.osim";
  const testing::CliRun run = Run("simulate " + model + " --duration 0.05 --out " + Path("sim") +
                                  " --export " + Path("sim.glb"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(testing::CountOccurrences(run.err,
                                      "so they are not drawn: /forceset/spring, "
                                      "/forceset/act"),
            1)
      << run.err;
  EXPECT_EQ(testing::CountOccurrences(run.err, "FunctionBasedPath"), 1) << run.err;
}

TEST_F(SimulateExportPathsTest, RenderShadesMusclesByTheStatesActivations) {
  // Every arm26 muscle at activation 0 (blue) or 1 (red), in OpenSim 4 labels.
  auto render = [&](const std::string& activation) {
    const std::vector<std::string> muscles = {"TRIlong", "TRIlat",   "TRImed",
                                              "BIClong", "BICshort", "BRA"};
    std::string header =
        "states\nversion=1\nnRows=1\nnColumns=" + std::to_string(muscles.size() + 2) +
        "\ninDegrees=no\nendheader\ntime\t/jointset/r_elbow/r_elbow_flex/value";
    std::string row = "0\t1.2";
    for (const std::string& m : muscles) {
      header += "\t/forceset/" + m + "/activation";
      row += "\t" + activation;
    }
    std::ofstream(Path("states.sto")) << header << "\n" << row << "\n";
    const testing::CliRun run =
        Run("render " + kArm26 + " --vis none --states " + Path("states.sto") +
            " --width 120 --height 160 --out " + Path("shaded.png"));
    EXPECT_EQ(run.exit_code, 0) << run.err;
    return RedAndBluePixels(viz::DecodePng(viz::ReadFileBytes(Path("shaded.png")), "shaded.png"));
  };
  const auto [red_inactive, blue_inactive] = render("0");
  EXPECT_EQ(red_inactive, 0);
  EXPECT_GT(blue_inactive, 200);
  const auto [red_active, blue_active] = render("1");
  EXPECT_GT(red_active, 200);
  EXPECT_EQ(blue_active, 0);
}

}  // namespace
}  // namespace sinew

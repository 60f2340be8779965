// Visualization costs on a real model: Rajagopal2016 (23 bodies, 81 .vtp meshes) driven by
// 599 frames of the Hamner running motion.
#include <benchmark/benchmark.h>
#include <sinew/io/mesh_file.h>
#include <sinew/io/osim_reader.h>
#include <sinew/io/storage.h>
#include <sinew/viz/gltf_writer.h>
#include <sinew/viz/html_viewer.h>
#include <sinew/viz/motion_poses.h>
#include <sinew/viz/path_lines.h>
#include <sinew/viz/rasterizer.h>

namespace sinew::viz {
namespace {

const std::string kData = SINEW_TEST_DATA_DIR;
const std::string kModel =
    kData + "/opensim-org/opensim-models/Models/Rajagopal/Rajagopal2016.osim";
const std::string kGeometry = kData + "/opensim-org/opensim-models/Geometry";
const std::string kMotion = kData +
                            "/opensim-org/opensim-models/Pipelines/Hamner/outputReference/"
                            "ResultsIK/subject02_running_ik.mot";

VisualScene MeshScene(const model::ModelSpec& spec) {
  VisualOptions options;
  options.mode = VisType::kMesh;
  options.geometry_dirs = {kGeometry};
  return BuildVisualScene(spec, options);
}

// Finding and reading all 81 meshes of the model (ascii .vtp).
void BM_BuildMeshScene(benchmark::State& state) {
  const model::ModelSpec spec = io::ReadOsim(kModel);
  for (auto _ : state) benchmark::DoNotOptimize(MeshScene(spec));
}
BENCHMARK(BM_BuildMeshScene)->Unit(benchmark::kMillisecond);

// Forward kinematics of every motion row into body poses.
void BM_MotionFromTable(benchmark::State& state) {
  const model::ModelSpec spec = io::ReadOsim(kModel);
  const io::Storage table = io::ReadStorage(kMotion);
  for (auto _ : state) benchmark::DoNotOptimize(MotionFromTable(spec, table, nullptr));
}
BENCHMARK(BM_MotionFromTable)->Unit(benchmark::kMillisecond);

// The .glb with 81 meshes and 599 frames x 23 bodies of animation.
void BM_WriteGlb(benchmark::State& state) {
  const model::ModelSpec spec = io::ReadOsim(kModel);
  const VisualScene scene = MeshScene(spec);
  const BodyMotion motion = MotionFromTable(spec, io::ReadStorage(kMotion), nullptr);
  size_t bytes = 0;
  for (auto _ : state) {
    std::vector<uint8_t> glb = WriteGlb(scene, motion, spec.name);
    bytes = glb.size();
    benchmark::DoNotOptimize(glb);
  }
  state.counters["MB"] = bytes / 1e6;
}
BENCHMARK(BM_WriteGlb)->Unit(benchmark::kMillisecond);

// The HTML page around that .glb (base64 of the model and of three.js).
void BM_MakeViewerHtml(benchmark::State& state) {
  const model::ModelSpec spec = io::ReadOsim(kModel);
  const std::vector<uint8_t> glb = WriteGlb(
      MeshScene(spec), MotionFromTable(spec, io::ReadStorage(kMotion), nullptr), spec.name);
  for (auto _ : state) benchmark::DoNotOptimize(MakeViewerHtml(glb, spec.name));
}
BENCHMARK(BM_MakeViewerHtml)->Unit(benchmark::kMillisecond);

// One 800x800 software-rendered picture of the meshed model (2x2 supersampled).
void BM_RenderScene(benchmark::State& state) {
  const model::ModelSpec spec = io::ReadOsim(kModel);
  const VisualScene scene = MeshScene(spec);
  const std::vector<Transform> X_GB = DefaultPoseMotion(spec).X_GB[0];
  RenderOptions options;
  const Camera camera = FrameCamera(SceneBounds(scene, X_GB), Vec3(1, 0.35, 0.8), 1.0);
  for (auto _ : state) benchmark::DoNotOptimize(RenderScene(scene, X_GB, camera, options));
}
BENCHMARK(BM_RenderScene)->Unit(benchmark::kMillisecond);

// Every one of the 80 paths at every motion row, wrapped, with the points along the arcs.
void BM_CalcPathLines(benchmark::State& state) {
  const model::ModelSpec spec = io::ReadOsim(kModel);
  const BodyMotion motion = MotionFromTable(spec, io::ReadStorage(kMotion), nullptr);
  size_t vertices = 0;
  for (auto _ : state) {
    const PathLines lines = CalcPathLines(spec, motion, nullptr);
    vertices = 0;
    for (const auto& frame : lines.vertices) {
      for (const auto& line : frame) vertices += line.size();
    }
    benchmark::DoNotOptimize(lines);
  }
  state.counters["vertices"] = static_cast<double>(vertices);
}
BENCHMARK(BM_CalcPathLines)->Unit(benchmark::kMillisecond);

// The .glb of BM_WriteGlb with the paths: one line mesh per frame.
void BM_WriteGlbWithPaths(benchmark::State& state) {
  const model::ModelSpec spec = io::ReadOsim(kModel);
  const VisualScene scene = MeshScene(spec);
  const BodyMotion motion = MotionFromTable(spec, io::ReadStorage(kMotion), nullptr);
  const PathLines lines = CalcPathLines(spec, motion, nullptr);
  size_t bytes = 0;
  for (auto _ : state) {
    std::vector<uint8_t> glb = WriteGlb(scene, motion, spec.name, &lines);
    bytes = glb.size();
    benchmark::DoNotOptimize(glb);
  }
  state.counters["MB"] = bytes / 1e6;
}
BENCHMARK(BM_WriteGlbWithPaths)->Unit(benchmark::kMillisecond);

// The HTML page around that .glb.
void BM_MakeViewerHtmlWithPaths(benchmark::State& state) {
  const model::ModelSpec spec = io::ReadOsim(kModel);
  const BodyMotion motion = MotionFromTable(spec, io::ReadStorage(kMotion), nullptr);
  const PathLines lines = CalcPathLines(spec, motion, nullptr);
  const std::vector<uint8_t> glb = WriteGlb(MeshScene(spec), motion, spec.name, &lines);
  size_t bytes = 0;
  for (auto _ : state) {
    const std::string page = MakeViewerHtml(glb, spec.name);
    bytes = page.size();
    benchmark::DoNotOptimize(page);
  }
  state.counters["MB"] = bytes / 1e6;
}
BENCHMARK(BM_MakeViewerHtmlWithPaths)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace sinew::viz

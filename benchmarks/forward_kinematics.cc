// Forward kinematics of the Hamner full-body model (37 coordinates, CustomJoints with
// SimmSplines): body poses per pose, and poses plus the 37 marker positions. Goal: < 5 us/pose.
#include <benchmark/benchmark.h>
#include <sinew/io/osim_reader.h>
#include <sinew/kinematics/forward_kinematics.h>
#include <sinew/kinematics/kinematic_tree.h>

#include <cmath>
#include <string>
#include <vector>

namespace {

const sinew::model::ModelSpec& Hamner() {
  static const sinew::model::ModelSpec spec = sinew::io::ReadOsim(
      std::string(SINEW_TEST_DATA_DIR) +
      "/opensim-org/opensim-models/Pipelines/Hamner/outputReference/subject02_registered.osim");
  return spec;
}

// A pose away from the defaults so every spline is evaluated between knots.
std::vector<double> SomePose(const sinew::kinematics::KinematicTree& tree) {
  std::vector<double> q = tree.default_q();
  for (size_t i = 0; i < q.size(); ++i) q[i] += 0.2 * std::sin(1.3 * static_cast<double>(i));
  return q;
}

void BM_HamnerBodyPoses(benchmark::State& state) {
  const sinew::kinematics::KinematicTree tree(Hamner());
  std::vector<double> q = SomePose(tree);
  std::vector<sinew::Transform> X(tree.num_bodies());
  for (auto _ : state) {
    q[0] += 1e-9;  // keep the compiler from hoisting the work
    sinew::kinematics::CalcBodyPoses(tree, q, X);
    benchmark::DoNotOptimize(X.data());
  }
  state.counters["coordinates"] = tree.num_coordinates();
  state.counters["bodies"] = tree.num_bodies();
}
BENCHMARK(BM_HamnerBodyPoses);

void BM_HamnerBodyPosesAndMarkers(benchmark::State& state) {
  const sinew::model::ModelSpec& spec = Hamner();
  const sinew::kinematics::KinematicTree tree(spec);
  std::vector<double> q = SomePose(tree);
  std::vector<sinew::Transform> X(tree.num_bodies());
  std::vector<sinew::Vec3> markers(spec.markers.size());
  for (auto _ : state) {
    q[0] += 1e-9;
    sinew::kinematics::CalcBodyPoses(tree, q, X);
    for (size_t m = 0; m < spec.markers.size(); ++m) {
      markers[m] = X[spec.markers[m].body] * spec.markers[m].location;
    }
    benchmark::DoNotOptimize(markers.data());
  }
}
BENCHMARK(BM_HamnerBodyPosesAndMarkers);

void BM_HamnerBodyVelocities(benchmark::State& state) {
  const sinew::kinematics::KinematicTree tree(Hamner());
  const std::vector<double> q = SomePose(tree);
  std::vector<double> u(q.size(), 0.5);
  std::vector<sinew::Transform> X(tree.num_bodies());
  std::vector<sinew::SpatialVec> V(tree.num_bodies());
  sinew::kinematics::CalcBodyPoses(tree, q, X);
  for (auto _ : state) {
    u[0] += 1e-9;
    sinew::kinematics::CalcBodyVelocities(tree, q, u, X, V);
    benchmark::DoNotOptimize(V.data());
  }
}
BENCHMARK(BM_HamnerBodyVelocities);

}  // namespace

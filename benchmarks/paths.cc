// Muscle paths of Rajagopal2016 (80 muscles + 17 other path forces, 46 PathWraps over 40
// cylinders): lengths and lengthening speeds of every path per pose (goal < 10 us), and the
// moment arms of every path about every free coordinate (goal < 50 us). The pose is a mid-stance
// like pose away from the defaults, so knee splines and several wraps are active.
#include <benchmark/benchmark.h>
#include <sinew/io/osim_reader.h>
#include <sinew/kinematics/coordinate_couplers.h>
#include <sinew/kinematics/forward_kinematics.h>
#include <sinew/kinematics/kinematic_tree.h>
#include <sinew/paths/path_analysis.h>
#include <sinew/paths/path_loads.h>
#include <sinew/paths/path_set.h>

#include <cmath>
#include <string>
#include <vector>

namespace {

struct Rajagopal {
  Rajagopal()
      : spec(sinew::io::ReadOsim(std::string(SINEW_TEST_DATA_DIR) +
                                 "/opensim-org/opensim-models/Models/Rajagopal/Rajagopal2016.osim")),
        tree(spec),
        couplers(spec),
        paths(spec) {}
  sinew::model::ModelSpec spec;
  sinew::kinematics::KinematicTree tree;
  sinew::kinematics::CoordinateCouplers couplers;
  sinew::paths::PathSet paths;

  std::vector<double> SomePose() const {
    std::vector<double> q = tree.default_q();
    for (size_t i = 0; i < q.size(); ++i) q[i] += 0.3 * std::sin(1.3 * static_cast<double>(i));
    couplers.Apply(q);
    return q;
  }
  std::vector<int> FreeCoordinates() const {
    std::vector<int> free;
    for (size_t c = 0; c < spec.coordinates.size(); ++c) {
      if (!spec.coordinates[c].locked && !couplers.Drives(static_cast<int>(c))) {
        free.push_back(static_cast<int>(c));
      }
    }
    return free;
  }
};

const Rajagopal& Model() {
  static const Rajagopal model;
  return model;
}

// Body poses and velocities, then every path's state, length and lengthening speed.
void BM_RajagopalPathLengthsAndSpeeds(benchmark::State& state) {
  const Rajagopal& m = Model();
  std::vector<double> q = m.SomePose();
  std::vector<double> u(q.size(), 0.5);
  m.couplers.ApplySpeeds(q, u);
  std::vector<sinew::Transform> X_GB(static_cast<size_t>(m.tree.num_bodies()));
  std::vector<sinew::SpatialVec> V_GB(static_cast<size_t>(m.tree.num_bodies()));
  sinew::paths::PathState path_state;
  std::vector<double> lengths(m.paths.paths().size()), speeds(lengths.size());
  int wrapped = 0;
  for (auto _ : state) {
    q[0] += 1e-12;  // keep the compiler from hoisting the work
    sinew::kinematics::CalcBodyPoses(m.tree, q, X_GB);
    sinew::kinematics::CalcBodyVelocities(m.tree, q, u, X_GB, V_GB);
    wrapped = 0;
    for (size_t p = 0; p < lengths.size(); ++p) {
      m.paths.paths()[p].CalcState(q, X_GB, path_state);
      lengths[p] = path_state.length;
      speeds[p] = sinew::paths::CalcLengtheningSpeed(path_state, X_GB, V_GB, u);
      for (const sinew::paths::PathPointState& point : path_state.points) {
        wrapped += point.arc_length_to_next >= 0.0 ? 1 : 0;
      }
    }
    benchmark::DoNotOptimize(lengths.data());
    benchmark::DoNotOptimize(speeds.data());
  }
  state.counters["paths"] = static_cast<double>(lengths.size());
  state.counters["wrapped"] = wrapped;
}
BENCHMARK(BM_RajagopalPathLengthsAndSpeeds);

// What `sinew analyze` does per frame: lengths, speeds and the moment arms of every path about
// every free coordinate (couplers moving the patellae along).
void BM_RajagopalMomentArms(benchmark::State& state) {
  const Rajagopal& m = Model();
  const std::vector<int> free = m.FreeCoordinates();
  sinew::paths::PathAnalysis analysis(m.spec, m.tree, m.couplers, m.paths, free);
  std::vector<double> q = m.SomePose();
  std::vector<double> u(q.size(), 0.5);
  m.couplers.ApplySpeeds(q, u);
  for (auto _ : state) {
    q[0] += 1e-12;
    analysis.Calc(q, u);
    benchmark::DoNotOptimize(analysis.lengths().data());
  }
  state.counters["paths"] = static_cast<double>(m.paths.paths().size());
  state.counters["coordinates"] = static_cast<double>(free.size());
}
BENCHMARK(BM_RajagopalMomentArms);

}  // namespace

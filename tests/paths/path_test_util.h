// Helpers shared by the path tests: a model read with its tree, couplers and paths, and the
// path lengths at a pose (for finite differences).
#pragma once

#include <sinew/io/osim_reader.h>
#include <sinew/kinematics/coordinate_couplers.h>
#include <sinew/kinematics/forward_kinematics.h>
#include <sinew/kinematics/kinematic_tree.h>
#include <sinew/paths/geometry_path.h>
#include <sinew/paths/path_set.h>

#include <span>
#include <string>
#include <vector>

namespace sinew::paths::testing {

inline const std::string kDataDir = SINEW_TEST_DATA_DIR;

/// A model with everything the path code needs.
struct PathModel {
  explicit PathModel(const std::string& file)
      : spec(io::ReadOsim(file)), tree(spec), couplers(spec), paths(spec) {}
  model::ModelSpec spec;
  kinematics::KinematicTree tree;
  kinematics::CoordinateCouplers couplers;
  PathSet paths;

  /// Index of the path whose owner is `name` (-1 when none).
  int FindPath(const std::string& name) const {
    for (size_t p = 0; p < paths.paths().size(); ++p) {
      if (paths.paths()[p].name() == name) return static_cast<int>(p);
    }
    return -1;
  }

  /// Poses and state of path p at q (as given: couplers not applied).
  PathState CalcState(int p, std::span<const double> q) const {
    std::vector<Transform> X_GB(static_cast<size_t>(tree.num_bodies()));
    kinematics::CalcBodyPoses(tree, q, X_GB);
    PathState state;
    paths.paths()[static_cast<size_t>(p)].CalcState(q, X_GB, state);
    return state;
  }
  double CalcLength(int p, std::span<const double> q) const { return CalcState(p, q).length; }
};

}  // namespace sinew::paths::testing

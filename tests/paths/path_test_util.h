// Helpers shared by the path tests: a model read with its tree, couplers and paths, and the
// path lengths at a pose (for finite differences).
#pragma once

#include <gtest/gtest.h>
#include <sinew/io/osim_reader.h>
#include <sinew/kinematics/coordinate_couplers.h>
#include <sinew/kinematics/forward_kinematics.h>
#include <sinew/kinematics/kinematic_tree.h>
#include <sinew/paths/geometry_path.h>
#include <sinew/paths/path_set.h>

#include <filesystem>
#include <fstream>
#include <span>
#include <sstream>
#include <string>
#include <vector>

namespace sinew::paths::testing {

inline const std::string kDataDir = SINEW_TEST_DATA_DIR;

/// OpenSim's test_wrapAllVis.osim: one knee-extensor path over six wrap objects, all inactive.
inline const std::string kWrapAllVis =
    kDataDir + "/opensim-org/opensim-core/OpenSim/Tools/Test/test_wrapAllVis.osim";

/// A copy of test_wrapAllVis.osim (in the test's temporary folder) whose WrapTorus is active:
/// its `active` is the first after its name.
inline std::string WriteWrapAllVisWithActiveTorus() {
  std::ifstream in(kWrapAllVis);
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::string text = buffer.str();
  const std::string inactive = "<active>false</active>";
  const size_t torus = text.find("<WrapTorus name=\"KnExt_at_fem_torus_r\">");
  text.replace(text.find(inactive, torus), inactive.size(), "<active>true</active>");
  const std::string copy =
      (std::filesystem::path(::testing::TempDir()) / "test_wrapAllVis_torus.osim").string();
  std::ofstream(copy) << text;
  return copy;
}

/// A model with everything the path code needs.
struct PathModel {
  explicit PathModel(const std::string& file,
                     CylinderRefinement refinement = CylinderRefinement::kSeveralWraps)
      : spec(io::ReadOsim(file)), tree(spec), couplers(spec), paths(spec, refinement) {}
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

  /// Length of path p at q through the points of `at` (its state at another pose): the same
  /// points, each wrap's tangent points kept fixed on the wrap's body, the same arc lengths.
  /// Its derivative at the pose of `at` is what the analytic moment arms and lengthening speeds
  /// are (wrap_surface.h); it equals the derivative of the length wrapped afresh where the
  /// wrapped path is the shortest over the surface (the envelope argument).
  double CalcLengthThrough(int p, std::span<const double> q, const PathState& at) const {
    std::vector<Transform> X_GB(static_cast<size_t>(tree.num_bodies()));
    kinematics::CalcBodyPoses(tree, q, X_GB);
    const GeometryPath& path = paths.paths()[static_cast<size_t>(p)];
    double length = 0.0;
    Vec3 p_G_previous = Vec3::Zero();
    for (size_t i = 0; i < at.points.size(); ++i) {
      const PathPointState& s = at.points[i];
      const Vec3 p_BP =
          s.point >= 0 ? path.points()[static_cast<size_t>(s.point)].CalcLocationInBody(q) : s.p_BP;
      const Vec3 p_G = X_GB[static_cast<size_t>(s.body)] * p_BP;
      if (i > 0) {
        const double arc = at.points[i - 1].arc_length_to_next;
        length += arc >= 0.0 ? arc : (p_G - p_G_previous).norm();
      }
      p_G_previous = p_G;
    }
    return length;
  }

  /// Whether path p is wrapped over a surface in `state` (it has tangent points).
  static bool IsWrapped(const PathState& state) {
    for (const PathPointState& s : state.points) {
      if (s.wrap >= 0) return true;
    }
    return false;
  }
};

}  // namespace sinew::paths::testing

// OpenSim's MuscleAnalysis quantities of every path of a model at one pose: length, lengthening
// speed and moment arms about chosen coordinates, all analytic.
#pragma once

#include <sinew/kinematics/coordinate_couplers.h>
#include <sinew/kinematics/kinematic_tree.h>
#include <sinew/model/model_spec.h>
#include <sinew/paths/path_loads.h>
#include <sinew/paths/path_set.h>
#include <sinew/paths/speed_columns.h>

#include <span>
#include <vector>

namespace sinew::paths {

/// Evaluates a PathSet pose by pose. Holds references to its arguments (they must outlive it)
/// and its own workspace, so one instance per thread.
class PathAnalysis {
 public:
  /// `coordinates`: indices into ModelSpec::coordinates for the moment arms.
  PathAnalysis(const model::ModelSpec& spec, const kinematics::KinematicTree& tree,
               const kinematics::CoordinateCouplers& couplers, const PathSet& paths,
               std::vector<int> coordinates);

  /// Evaluates every path at coordinates q and speeds u (ModelSpec::coordinates order; the
  /// couplers already applied to both, e.g. CoordinateCouplers::Apply and ApplySpeeds).
  void Calc(std::span<const double> q, std::span<const double> u);

  /// Per path (PathSet order): length (m) and lengthening speed (m/s; with moment arms, a
  /// GeometryPath's is dL/du . u from the same length gradient, else the segment sum of
  /// CalcLengtheningSpeed: equal to rounding).
  const std::vector<double>& lengths() const { return lengths_; }
  const std::vector<double>& lengthening_speeds() const { return speeds_; }
  /// Moment arm (m, or dimensionless about a translational coordinate) of path p about the
  /// k-th coordinate of the list: -c . dL/du with c OpenSim's coupling vector; for a
  /// FunctionBasedPath, as OpenSim, -dL/dq_k alone (0 about a coordinate it does not list).
  double moment_arm(size_t k, size_t p) const { return moment_arms_[k * lengths_.size() + p]; }
  /// OpenSim's moment arm, as its MomentArmSolver (MuscleAnalysis) computes it, and what `sinew
  /// analyze` writes: moment_arm(k, p), except on a path with stale tangent points (several
  /// wrap objects), where OpenSim pulls them along the directions from the locations it read
  /// first but applies the forces where the points are now (AddStaleTangentPointShift); there
  /// it is not a derivative of the length (docs/paths.md), and Sinew's dynamics use
  /// moment_arm.
  double opensim_moment_arm(size_t k, size_t p) const {
    const size_t i = k * lengths_.size() + p;
    return stale_[p] ? opensim_moment_arms_[i] : moment_arms_[i];
  }
  const std::vector<int>& coordinates() const { return coordinates_; }

 private:
  const model::ModelSpec& spec_;
  const kinematics::KinematicTree& tree_;
  const kinematics::CoordinateCouplers& couplers_;
  const PathSet& paths_;
  std::vector<int> coordinates_;
  // Workspace.
  std::vector<Transform> X_GB_;
  std::vector<SpatialVec> V_GB_;
  SpeedColumns columns_;
  PathState state_;
  std::vector<double> dL_du_, shifted_dL_du_;
  // Per moment-arm coordinate: the coordinate itself when no constraint row involves it (it
  // moves alone, coupling 1), else -1 and its place in solved_coordinates_.
  std::vector<int> alone_;
  std::vector<size_t> solved_index_;
  // The coordinates whose coupling vectors are solved for at each pose, and those vectors.
  std::vector<int> solved_coordinates_;
  std::vector<std::vector<double>> couplings_;
  // The nonzero entries of those coupling vectors, laid end to end: those of
  // solved_coordinates_[s] are coupled_[coupled_begin_[s] .. coupled_begin_[s + 1]).
  struct Coupled {
    size_t coordinate;
    double coupling;
  };
  std::vector<Coupled> coupled_;
  std::vector<size_t> coupled_begin_;
  std::vector<double> lengths_, speeds_, moment_arms_;
  // Per path: whether it has stale tangent points at this pose; only then are its
  // opensim_moment_arms_ filled (else they are its moment_arms_).
  std::vector<char> stale_;
  std::vector<double> opensim_moment_arms_;

  // -c . g for the k-th moment-arm coordinate (c its coupling vector at this pose).
  double MinusCoupled(size_t k, const double* g) const;
};

}  // namespace sinew::paths

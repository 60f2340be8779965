// The velocity of every body for each unit coordinate speed: column k of the system Jacobian,
// V_GB = sum_k V_GB^(k) u_k. With it, any quantity that is linear in the speeds (a path's
// lengthening speed, the power of a force) gives its derivative with respect to every
// coordinate speed without finite differences.
#pragma once

#include <sinew/kinematics/kinematic_tree.h>
#include <sinew/math/transform.h>

#include <span>
#include <vector>

namespace sinew::paths {

/// V_GB^(k) = [w_GB; v_GBo] in G of every body when u = e_k (all other speeds zero).
struct SpeedColumns {
  int num_bodies = 0;
  int num_coordinates = 0;
  std::vector<SpatialVec> V_GB;  ///< column k, body b at V_GB[k * num_bodies + b].
  /// Per body: the coordinates whose columns can move it (those of the joints between it and
  /// ground); every other column is zero at that body.
  std::vector<std::vector<int>> support;

  std::span<const SpatialVec> Column(int k) const {
    return {V_GB.data() + static_cast<size_t>(k) * num_bodies, static_cast<size_t>(num_bodies)};
  }
};

/// Fills `columns` at q with body poses X_GB (kinematics::CalcBodyPoses at the same q): one
/// joint velocity map per coordinate (kinematics::CalcBodyVelocityColumns).
void CalcSpeedColumns(const kinematics::KinematicTree& tree, std::span<const double> q,
                      std::span<const Transform> X_GB, SpeedColumns& columns);

}  // namespace sinew::paths

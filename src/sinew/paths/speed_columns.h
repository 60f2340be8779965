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

/// V_GB^(k) = [w_GB; v_GBo] in G of every body when u = e_k (all other speeds zero), kept only
/// where it is not zero: at body b, for the coordinates of b's support (the joints between b
/// and ground, KinematicTree::support), contiguous per body.
struct SpeedColumns {
  /// The tree of the last CalcSpeedColumns (it must outlive the columns' use).
  const kinematics::KinematicTree* tree = nullptr;
  /// Body b's columns at V_GB[tree->support_offset(b) + i], for coordinate tree->support(b)[i].
  std::vector<SpatialVec> V_GB;
  /// When not empty, only the bodies these tree joints place are filled
  /// (kinematics::ListJointsToBodies of the bodies wanted, set once by the user); the columns
  /// of other bodies are then not computed and must not be read.
  std::vector<int> joints;

  /// The coordinates whose columns can move body b; every other column is zero there.
  std::span<const int> Support(int b) const { return tree->support(b); }
  /// Body b's columns, one per coordinate of Support(b), in that order.
  std::span<const SpatialVec> AtBody(int b) const {
    return {V_GB.data() + tree->support_offset(b), tree->support(b).size()};
  }
};

/// Fills `columns` at q with body poses X_GB (kinematics::CalcBodyPoses at the same q): one
/// joint velocity map per joint carried outward over its subtree
/// (kinematics::CalcSupportVelocityColumns). No heap use once `columns` is sized.
void CalcSpeedColumns(const kinematics::KinematicTree& tree, std::span<const double> q,
                      std::span<const Transform> X_GB, SpeedColumns& columns);

}  // namespace sinew::paths

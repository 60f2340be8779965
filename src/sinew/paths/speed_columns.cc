#include <sinew/kinematics/forward_kinematics.h>
#include <sinew/paths/speed_columns.h>

namespace sinew::paths {

void CalcSpeedColumns(const kinematics::KinematicTree& tree, std::span<const double> q,
                      std::span<const Transform> X_GB, SpeedColumns& columns) {
  columns.tree = &tree;
  columns.V_GB.resize(static_cast<size_t>(tree.support_offset(tree.num_bodies())));
  kinematics::CalcSupportVelocityColumns(tree, q, X_GB, columns.V_GB, columns.joints);
}

}  // namespace sinew::paths

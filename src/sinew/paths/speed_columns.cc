#include <sinew/kinematics/forward_kinematics.h>
#include <sinew/paths/speed_columns.h>

namespace sinew::paths {

void CalcSpeedColumns(const kinematics::KinematicTree& tree, std::span<const double> q,
                      std::span<const Transform> X_GB, SpeedColumns& columns) {
  columns.num_bodies = tree.num_bodies();
  columns.num_coordinates = tree.num_coordinates();
  columns.V_GB.resize(static_cast<size_t>(columns.num_bodies) * columns.num_coordinates);
  kinematics::CalcBodyVelocityColumns(tree, q, X_GB, columns.V_GB);
  columns.support.resize(static_cast<size_t>(columns.num_bodies));
  columns.support[model::kGroundIndex].clear();
  for (const kinematics::TreeJoint& t : tree.joints()) {
    std::vector<int>& support = columns.support[static_cast<size_t>(t.outboard)];
    support = columns.support[static_cast<size_t>(t.inboard)];
    support.insert(support.end(), t.q_index.begin(), t.q_index.begin() + t.nq);
  }
}

}  // namespace sinew::paths

#include <sinew/kinematics/forward_kinematics.h>
#include <sinew/paths/speed_columns.h>

namespace sinew::paths {

void CalcSpeedColumns(const kinematics::KinematicTree& tree, std::span<const double> q,
                      std::span<const Transform> X_GB, SpeedColumns& columns) {
  columns.num_bodies = tree.num_bodies();
  columns.num_coordinates = tree.num_coordinates();
  columns.V_GB.resize(static_cast<size_t>(columns.num_bodies) * columns.num_coordinates);
  std::vector<double> u(static_cast<size_t>(columns.num_coordinates), 0.0);
  for (int k = 0; k < columns.num_coordinates; ++k) {
    u[static_cast<size_t>(k)] = 1.0;
    kinematics::CalcBodyVelocities(
        tree, q, u, X_GB,
        std::span<SpatialVec>(columns.V_GB.data() + static_cast<size_t>(k) * columns.num_bodies,
                              static_cast<size_t>(columns.num_bodies)));
    u[static_cast<size_t>(k)] = 0.0;
  }
}

}  // namespace sinew::paths

#include <sinew/kinematics/forward_kinematics.h>
#include <sinew/paths/coupling_vector.h>
#include <sinew/paths/path_analysis.h>

namespace sinew::paths {

PathAnalysis::PathAnalysis(const model::ModelSpec& spec, const kinematics::KinematicTree& tree,
                           const kinematics::CoordinateCouplers& couplers, const PathSet& paths,
                           std::vector<int> coordinates)
    : spec_(spec),
      tree_(tree),
      couplers_(couplers),
      paths_(paths),
      coordinates_(std::move(coordinates)),
      X_GB_(static_cast<size_t>(tree.num_bodies())),
      V_GB_(static_cast<size_t>(tree.num_bodies())),
      dL_du_(static_cast<size_t>(tree.num_coordinates())),
      shifted_dL_du_(dL_du_.size()),
      alone_(coordinates_.size(), -1),
      solved_index_(coordinates_.size(), 0),
      lengths_(paths.paths().size()),
      speeds_(paths.paths().size()),
      moment_arms_(coordinates_.size() * paths.paths().size()),
      stale_(paths.paths().size(), 0),
      opensim_moment_arms_(moment_arms_.size()) {
  // A coordinate that is not locked and in no coupler is in no constraint row: its coupling
  // vector is e_j at every pose (CalcCouplingVectors), so only the others are solved for.
  for (size_t k = 0; k < coordinates_.size(); ++k) {
    const int j = coordinates_[k];
    if (!spec.coordinates.at(static_cast<size_t>(j)).locked && !couplers.Involves(j)) {
      alone_[k] = j;
    } else {
      solved_index_[k] = solved_coordinates_.size();
      solved_coordinates_.push_back(j);
    }
  }
  couplings_.resize(solved_coordinates_.size());
  // The speed columns only of the bodies a path point or tangent point can be on (and those
  // inboard of them): Rajagopal's arms carry no path.
  std::vector<int> bodies;
  for (const GeometryPath& path : paths.paths()) {
    for (const PathPoint& point : path.points()) bodies.push_back(point.body);
    for (const PathWrap& wrap : path.wraps()) bodies.push_back(wrap.body);
  }
  columns_.joints = kinematics::ListJointsToBodies(tree, bodies);
}

void PathAnalysis::Calc(std::span<const double> q, std::span<const double> u) {
  kinematics::CalcBodyPoses(tree_, q, X_GB_);
  const bool moment_arms = !coordinates_.empty();
  // With moment arms, a GeometryPath's dL/du gives its lengthening speed as well (dL/dt =
  // dL/du . u, the same sum over its segments in another order), so the body velocities are
  // not needed.
  if (!moment_arms) kinematics::CalcBodyVelocities(tree_, q, u, X_GB_, V_GB_);
  if (moment_arms) {
    CalcSpeedColumns(tree_, q, X_GB_, columns_);
    if (!solved_coordinates_.empty()) {
      CalcCouplingVectors(spec_, couplers_, q, solved_coordinates_, couplings_);
    }
    // Only the coordinates that move along (one, or a few with couplers) enter the sums.
    coupled_begin_.clear();
    coupled_.clear();
    for (const std::vector<double>& coupling : couplings_) {
      coupled_begin_.push_back(coupled_.size());
      for (size_t c = 0; c < coupling.size(); ++c) {
        if (coupling[c] != 0.0) coupled_.push_back({c, coupling[c]});
      }
    }
    coupled_begin_.push_back(coupled_.size());
  }
  const size_t num_paths = paths_.paths().size();
  for (size_t p = 0; p < num_paths; ++p) {
    paths_.paths()[p].CalcState(q, X_GB_, state_);
    lengths_[p] = state_.length;
    stale_[p] = moment_arms && state_.stale_tangent_points > 0;
    if (!moment_arms) {
      speeds_[p] = CalcLengtheningSpeed(state_, X_GB_, V_GB_, u);
      continue;
    }
    if (!state_.slopes.empty()) {
      // A FunctionBasedPath's speed reads no body velocity.
      speeds_[p] = CalcLengtheningSpeed(state_, X_GB_, {}, u);
      // A FunctionBasedPath: OpenSim reads its moment arm about each of its own coordinates
      // (zero about any other) without the MomentArmSolver, so coupled coordinates do not
      // move along.
      for (size_t k = 0; k < coordinates_.size(); ++k) {
        double r = 0.0;
        for (const LengthSlope& s : state_.slopes) {
          if (s.coordinate == coordinates_[k]) r = -s.dL_dq;
        }
        moment_arms_[k * num_paths + p] = r;
      }
      continue;
    }
    CalcLengthGradient(state_, X_GB_, columns_, dL_du_);
    double speed = 0.0;
    for (size_t c = 0; c < dL_du_.size(); ++c) speed += dL_du_[c] * u[c];
    speeds_[p] = speed;
    // Locals: the compiler need not reload the members after each store.
    const double* dL_du = dL_du_.data();
    const int* alone = alone_.data();
    double* r = moment_arms_.data() + p;
    for (size_t k = 0; k < coordinates_.size(); ++k, r += num_paths) {
      double sum = 0.0;
      if (alone[k] >= 0) {
        sum -= dL_du[alone[k]];  // the same sum, of one term times 1
      } else {
        const size_t s = solved_index_[k];
        for (size_t e = coupled_begin_[s]; e < coupled_begin_[s + 1]; ++e) {
          sum -= coupled_[e].coupling * dL_du[coupled_[e].coordinate];
        }
      }
      *r = sum;
    }
    // OpenSim's moment arms differ only where tangent points are stale.
    if (!stale_[p]) continue;
    shifted_dL_du_ = dL_du_;
    AddStaleTangentPointShift(state_, X_GB_, columns_, shifted_dL_du_);
    for (size_t k = 0; k < coordinates_.size(); ++k) {
      opensim_moment_arms_[k * num_paths + p] = MinusCoupled(k, shifted_dL_du_.data());
    }
  }
}

double PathAnalysis::MinusCoupled(size_t k, const double* g) const {
  if (alone_[k] >= 0) return -g[alone_[k]];
  double sum = 0.0;
  const size_t s = solved_index_[k];
  for (size_t e = coupled_begin_[s]; e < coupled_begin_[s + 1]; ++e) {
    sum -= coupled_[e].coupling * g[coupled_[e].coordinate];
  }
  return sum;
}

}  // namespace sinew::paths

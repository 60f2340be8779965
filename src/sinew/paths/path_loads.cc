#include <sinew/paths/path_loads.h>

#include <algorithm>
#include <span>
#include <vector>

namespace sinew::paths {
namespace {

// Velocity in G of a point p_BP of a body moving with V_GB = [w; v].
Vec3 StationVelocity(const Transform& X_GB, const SpatialVec& V_GB, const Vec3& p_BP) {
  return V_GB.tail<3>() + V_GB.head<3>().cross(X_GB.R * p_BP);
}

// e_i - e_(i-1) at point i: the direction a unit tension pulls point i in.
Vec3 PullDirection(const PathState& state, size_t i) {
  Vec3 pull = Vec3::Zero();
  if (i < state.e_G.size()) pull += state.e_G[i];
  if (i > 0) pull -= state.e_G[i - 1];
  return pull;
}

// The point forces of a path gathered into one wrench per body (moment about the body origin,
// in G): f . (v + w x r) = f . v + w . (r x f), so each coordinate costs a product per body,
// not per point.
struct BodyWrench {
  int body;
  SpatialVec F_G;  // [moment about the body origin; force], in G
};

// The wrench list, emptied; reused, so no heap use once sized.
std::vector<BodyWrench>& EmptyWrenches() {
  thread_local std::vector<BodyWrench> wrenches;
  wrenches.clear();
  return wrenches;
}

// Adds the force f_G at p_BP of `body` to that body's wrench (none for ground). The moment and
// the force go into the wrench's halves directly: a six-vector assembled from them in memory
// and read back whole stalls the store forwarding.
void AddPointForce(std::span<const Transform> X_GB, int body, const Vec3& p_BP, const Vec3& f_G,
                   std::vector<BodyWrench>& wrenches) {
  if (body == model::kGroundIndex) return;
  const Vec3 moment = (X_GB[body].R * p_BP).cross(f_G);
  // Consecutive points are mostly on one body: the last wrench first.
  BodyWrench* same = nullptr;
  if (!wrenches.empty() && wrenches.back().body == body) {
    same = &wrenches.back();
  } else {
    auto found = std::find_if(wrenches.begin(), wrenches.end(),
                              [&](const BodyWrench& w) { return w.body == body; });
    if (found != wrenches.end()) same = &*found;
  }
  if (same == nullptr) {
    wrenches.push_back({body, SpatialVec::Zero()});
    wrenches.back().F_G.head<3>() = moment;
    wrenches.back().F_G.tail<3>() = f_G;
  } else {
    same->F_G.head<3>() += moment;
    same->F_G.tail<3>() += f_G;
  }
}

// Q_k += the power of every wrench under unit speed k. Only the columns that move a body meet
// its wrench (kept contiguous per body): one six-vector product each, w . moment + v . force.
void AddWrenchPowers(const std::vector<BodyWrench>& wrenches, const SpeedColumns& columns,
                     std::span<double> Q) {
  for (const BodyWrench& w : wrenches) {
    const std::span<const int> support = columns.Support(w.body);
    const SpatialVec* V = columns.AtBody(w.body).data();
    for (size_t i = 0; i < support.size(); ++i) Q[support[i]] += w.F_G.dot(V[i]);
  }
}

}  // namespace

void CalcPathLoads(const PathState& state, std::span<const Transform> X_GB, double tension,
                   PathLoads& loads) {
  loads.point_forces.clear();
  loads.coordinate_forces.clear();
  for (size_t i = 0; i < state.points.size(); ++i) {
    const PathPointState& p = state.points[i];
    const Vec3 f_G = tension * PullDirection(state, i);
    loads.point_forces.push_back({p.body, p.p_BP, f_G});
    for (int axis = 0; axis < 3; ++axis) {
      if (p.coordinates[axis] == model::kNone) continue;
      loads.coordinate_forces.push_back(
          {p.coordinates[axis], f_G.dot(X_GB[p.body].R * p.dp_BP_dq[axis])});
    }
  }
  // A FunctionBasedPath: generalized forces only (OpenSim: tension times the moment arm).
  for (const LengthSlope& s : state.slopes) {
    loads.coordinate_forces.push_back({s.coordinate, -tension * s.dL_dq});
  }
}

void AddGeneralizedForces(const PathLoads& loads, std::span<const Transform> X_GB,
                          const SpeedColumns& columns, std::span<double> Q) {
  std::vector<BodyWrench>& wrenches = EmptyWrenches();
  for (const PointForce& f : loads.point_forces) {
    AddPointForce(X_GB, f.body, f.p_BP, f.f_G, wrenches);
  }
  AddWrenchPowers(wrenches, columns, Q);
  for (const CoordinateForce& f : loads.coordinate_forces) Q[f.coordinate] += f.value;
}

void CalcLengthGradient(const PathState& state, std::span<const Transform> X_GB,
                        const SpeedColumns& columns, std::span<double> dL_du) {
  std::fill(dL_du.begin(), dL_du.end(), 0.0);
  // AddGeneralizedForces of CalcPathLoads at a tension of -1 (which pushes: its generalized
  // force is +dL/du), term by term in the same order, without storing the loads.
  std::vector<BodyWrench>& wrenches = EmptyWrenches();
  bool moving = false;
  for (size_t i = 0; i < state.points.size(); ++i) {
    const PathPointState& p = state.points[i];
    AddPointForce(X_GB, p.body, p.p_BP, -PullDirection(state, i), wrenches);
    moving = moving || p.coordinates[0] != model::kNone || p.coordinates[1] != model::kNone ||
             p.coordinates[2] != model::kNone;
  }
  AddWrenchPowers(wrenches, columns, dL_du);
  for (size_t i = 0; moving && i < state.points.size(); ++i) {
    const PathPointState& p = state.points[i];
    for (int axis = 0; axis < 3; ++axis) {
      if (p.coordinates[axis] == model::kNone) continue;
      dL_du[p.coordinates[axis]] +=
          (-PullDirection(state, i)).dot(X_GB[p.body].R * p.dp_BP_dq[axis]);
    }
  }
  for (const LengthSlope& s : state.slopes) dL_du[s.coordinate] += s.dL_dq;
}

void AddStaleTangentPointShift(const PathState& state, std::span<const Transform> X_GB,
                               const SpeedColumns& columns, std::span<double> dL_du) {
  if (state.stale_tangent_points == 0) return;
  std::vector<BodyWrench>& wrenches = EmptyWrenches();
  const size_t n = state.points.size();
  for (size_t i = 0; i < n; ++i) {
    const PathPointState& p = state.points[i];
    if (p.wrap < 0 || p.p_BP_placed == p.p_BP) continue;
    // The pull of a tension of -1 along the segments to points of other bodies (OpenSim skips
    // a segment within one body; Sinew's forces along it, at the points as read, cancel).
    Vec3 push = Vec3::Zero();
    if (i + 1 < n && state.points[i + 1].body != p.body) push -= state.e_G[i];
    if (i > 0 && state.points[i - 1].body != p.body) push += state.e_G[i - 1];
    AddPointForce(X_GB, p.body, p.p_BP_placed, push, wrenches);
    AddPointForce(X_GB, p.body, p.p_BP, -push, wrenches);
  }
  AddWrenchPowers(wrenches, columns, dL_du);
}

double CalcLengtheningSpeed(const PathState& state, std::span<const Transform> X_GB,
                            std::span<const SpatialVec> V_GB, std::span<const double> u) {
  // A FunctionBasedPath: its lengthening_speed_function(q, u) when given, else sum dL/dq u.
  if (state.speed_function) {
    const size_t n = state.slopes.size();
    for (size_t i = 0; i < n; ++i) state.speed_arguments[n + i] = u[state.slopes[i].coordinate];
    return state.speed_function->CalcN(state.speed_arguments);
  }
  double speed = 0.0;
  for (const LengthSlope& s : state.slopes) speed += s.dL_dq * u[s.coordinate];
  Vec3 v_previous = Vec3::Zero();
  for (size_t i = 0; i < state.points.size(); ++i) {
    const PathPointState& p = state.points[i];
    Vec3 v_GP = StationVelocity(X_GB[p.body], V_GB[p.body], p.p_BP);
    for (int axis = 0; axis < 3; ++axis) {
      if (p.coordinates[axis] == model::kNone) continue;
      v_GP += X_GB[p.body].R * p.dp_BP_dq[axis] * u[p.coordinates[axis]];
    }
    if (i > 0 && state.points[i - 1].arc_length_to_next < 0.0) {
      speed += state.e_G[i - 1].dot(v_GP - v_previous);
    }
    v_previous = v_GP;
  }
  return speed;
}

}  // namespace sinew::paths

#include <sinew/common/error.h>
#include <sinew/kinematics/forward_kinematics.h>

#include <array>
#include <string>

namespace sinew::kinematics {
namespace {

// The joint's coordinates (or speeds) gathered from the model-wide vector.
std::array<double, 6> Gather(const TreeJoint& t, std::span<const double> values) {
  std::array<double, 6> local{};
  for (int k = 0; k < t.nq; ++k) local[k] = values[t.q_index[k]];
  return local;
}

}  // namespace

void CalcBodyPoses(const KinematicTree& tree, std::span<const double> q,
                   std::span<Transform> X_GB) {
  if (static_cast<int>(q.size()) < tree.num_coordinates() ||
      static_cast<int>(X_GB.size()) < tree.num_bodies()) {
    throw Error("CalcBodyPoses: q or X_GB is too short for the model");
  }
  X_GB[model::kGroundIndex] = Transform();
  for (const TreeJoint& t : tree.joints()) {
    const std::array<double, 6> q_local = Gather(t, q);
    const Transform X_FM = t.model->CalcX_FM(std::span<const double>(q_local.data(), t.nq));
    const Transform X_J1J2 = t.reversed ? X_FM.Inverse() : X_FM;
    X_GB[t.outboard] = X_GB[t.inboard] * t.X_IJ * X_J1J2 * t.X_JO;
  }
}

namespace {

void CheckVelocityArguments(const KinematicTree& tree, std::span<const double> q,
                            std::span<const Transform> X_GB, size_t num_velocities,
                            const char* function) {
  if (static_cast<int>(q.size()) < tree.num_coordinates() ||
      static_cast<int>(X_GB.size()) < tree.num_bodies() ||
      num_velocities < static_cast<size_t>(tree.num_bodies())) {
    throw Error(std::string(function) + ": q, u, X_GB or V_GB is too short for the model");
  }
}

// What joint t's own motion (its speeds us at its coordinates qs) adds to its outboard body's
// spatial velocity, in G: the angular velocity across the joint, and the velocity of the
// outboard origin it causes.
SpatialVec CalcJointTwistInG(const TreeJoint& t, std::span<const double> qs,
                             std::span<const double> us, std::span<const Transform> X_GB) {
  // V_FM in F from the joint's velocity map.
  const SpatialVec V_FM = t.model->CalcV_FM(qs, us);
  Vec3 w_rel = V_FM.head<3>(), v_rel = V_FM.tail<3>();
  // Relative motion of the outboard joint frame J2 in the inboard one J1, in J1. Reversed:
  // the motion of F in M: w_MF = -R_MF w_FM, v_MF = w_MF x p_MF - R_MF v_FM.
  if (t.reversed) {
    const Transform X_MF = t.model->CalcX_FM(qs).Inverse();
    w_rel = -(X_MF.R * w_rel);
    v_rel = w_rel.cross(X_MF.p) - X_MF.R * v_rel;
  }
  const Transform& X_GO = X_GB[t.outboard];
  const Transform X_GJ1 = X_GB[t.inboard] * t.X_IJ;
  const Vec3 p_GJ2 = X_GO * t.X_JO.Inverse().p;  // J2's origin in G
  SpatialVec V;
  V.head<3>() = X_GJ1.R * w_rel;
  V.tail<3>() = X_GJ1.R * v_rel + V.head<3>().cross(X_GO.p - p_GJ2);
  return V;
}

// The outboard body's velocity: the inboard body's, carried rigidly to the outboard origin,
// plus the joint's own twist.
void AddInboardVelocity(const TreeJoint& t, std::span<const Transform> X_GB,
                        std::span<SpatialVec> V_GB) {
  const Vec3 w_GI = V_GB[t.inboard].head<3>();
  const Vec3 v_GI = V_GB[t.inboard].tail<3>();
  SpatialVec& V = V_GB[t.outboard];
  V.head<3>() += w_GI;
  V.tail<3>() += v_GI + w_GI.cross(X_GB[t.outboard].p - X_GB[t.inboard].p);
}

}  // namespace

void CalcBodyVelocities(const KinematicTree& tree, std::span<const double> q,
                        std::span<const double> u, std::span<const Transform> X_GB,
                        std::span<SpatialVec> V_GB) {
  CheckVelocityArguments(tree, q, X_GB, V_GB.size(), "CalcBodyVelocities");
  if (static_cast<int>(u.size()) < tree.num_coordinates()) {
    throw Error("CalcBodyVelocities: q, u, X_GB or V_GB is too short for the model");
  }
  V_GB[model::kGroundIndex].setZero();
  for (const TreeJoint& t : tree.joints()) {
    const std::array<double, 6> q_local = Gather(t, q);
    const std::array<double, 6> u_local = Gather(t, u);
    V_GB[t.outboard] = CalcJointTwistInG(t, std::span<const double>(q_local.data(), t.nq),
                                         std::span<const double>(u_local.data(), t.nq), X_GB);
    AddInboardVelocity(t, X_GB, V_GB);
  }
}

void CalcBodyVelocityColumns(const KinematicTree& tree, std::span<const double> q,
                             std::span<const Transform> X_GB, std::span<SpatialVec> V_GB) {
  const size_t nb = static_cast<size_t>(tree.num_bodies());
  const size_t nc = static_cast<size_t>(tree.num_coordinates());
  CheckVelocityArguments(tree, q, X_GB, nc == 0 ? nb : V_GB.size() / nc, "CalcBodyVelocityColumns");
  for (size_t i = 0; i < nb * nc; ++i) V_GB[i].setZero();
  // Each coordinate's own joint twist (one velocity map per coordinate)...
  for (const TreeJoint& t : tree.joints()) {
    const std::array<double, 6> q_local = Gather(t, q);
    const std::span<const double> qs(q_local.data(), t.nq);
    for (int i = 0; i < t.nq; ++i) {
      std::array<double, 6> unit{};
      unit[static_cast<size_t>(i)] = 1.0;
      const size_t k = static_cast<size_t>(t.q_index[static_cast<size_t>(i)]);
      V_GB[k * nb + static_cast<size_t>(t.outboard)] +=
          CalcJointTwistInG(t, qs, std::span<const double>(unit.data(), t.nq), X_GB);
    }
  }
  // ... carried outward through the tree, in the tree's order (inboard bodies first).
  for (size_t k = 0; k < nc; ++k) {
    const std::span<SpatialVec> column = V_GB.subspan(k * nb, nb);
    for (const TreeJoint& t : tree.joints()) AddInboardVelocity(t, X_GB, column);
  }
}

std::vector<Vec3> CalcMassCenterLocations(const model::ModelSpec& spec,
                                          std::span<const Transform> X_GB) {
  std::vector<Vec3> p(spec.bodies.size());
  for (size_t b = 0; b < spec.bodies.size(); ++b) p[b] = X_GB[b] * spec.bodies[b].mass_center;
  return p;
}

std::vector<Vec3> CalcMarkerLocations(const model::ModelSpec& spec,
                                      std::span<const Transform> X_GB) {
  std::vector<Vec3> p(spec.markers.size());
  for (size_t m = 0; m < spec.markers.size(); ++m) {
    const model::MarkerSpec& marker = spec.markers[m];
    if (marker.body < 0 || marker.body >= static_cast<int>(X_GB.size())) {
      throw Error(marker.where, marker.name, "marker body out of range");
    }
    p[m] = X_GB[spec.markers[m].body] * spec.markers[m].location;
  }
  return p;
}

}  // namespace sinew::kinematics

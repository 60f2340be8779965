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

void CalcBodyVelocities(const KinematicTree& tree, std::span<const double> q,
                        std::span<const double> u, std::span<const Transform> X_GB,
                        std::span<SpatialVec> V_GB) {
  if (static_cast<int>(q.size()) < tree.num_coordinates() ||
      static_cast<int>(u.size()) < tree.num_coordinates() ||
      static_cast<int>(X_GB.size()) < tree.num_bodies() ||
      static_cast<int>(V_GB.size()) < tree.num_bodies()) {
    throw Error("CalcBodyVelocities: q, u, X_GB or V_GB is too short for the model");
  }
  V_GB[model::kGroundIndex].setZero();
  for (const TreeJoint& t : tree.joints()) {
    const std::array<double, 6> q_local = Gather(t, q);
    const std::array<double, 6> u_local = Gather(t, u);
    const std::span<const double> qs(q_local.data(), t.nq);
    // V_FM in F from the joint's velocity map.
    const SpatialVec V_FM = t.model->CalcV_FM(qs, std::span<const double>(u_local.data(), t.nq));
    Vec3 w_rel = V_FM.head<3>(), v_rel = V_FM.tail<3>();
    // Relative motion of the outboard joint frame J2 in the inboard one J1, in J1. Reversed:
    // the motion of F in M: w_MF = -R_MF w_FM, v_MF = w_MF x p_MF - R_MF v_FM.
    if (t.reversed) {
      const Transform X_MF = t.model->CalcX_FM(qs).Inverse();
      w_rel = -(X_MF.R * w_rel);
      v_rel = w_rel.cross(X_MF.p) - X_MF.R * v_rel;
    }
    const Transform& X_GI = X_GB[t.inboard];
    const Transform& X_GO = X_GB[t.outboard];
    const Transform X_GJ1 = X_GI * t.X_IJ;
    const Vec3 p_GJ2 = X_GO * t.X_JO.Inverse().p;  // J2's origin in G
    const Vec3 w_rel_G = X_GJ1.R * w_rel;
    const Vec3& w_GI = V_GB[t.inboard].head<3>();
    const Vec3& v_GI = V_GB[t.inboard].tail<3>();
    SpatialVec& V = V_GB[t.outboard];
    V.head<3>() = w_GI + w_rel_G;
    V.tail<3>() =
        v_GI + w_GI.cross(X_GO.p - X_GI.p) + X_GJ1.R * v_rel + w_rel_G.cross(X_GO.p - p_GJ2);
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

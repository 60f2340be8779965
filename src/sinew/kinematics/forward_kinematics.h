// Forward kinematics: body poses and velocities in ground from coordinates and speeds, and
// the ground positions of stations, mass centres and markers.
#pragma once

#include <sinew/kinematics/kinematic_tree.h>
#include <sinew/math/transform.h>
#include <sinew/model/model_spec.h>

#include <span>
#include <vector>

namespace sinew::kinematics {

/// X_GB for every body (ground included, identity) from q (ModelSpec::coordinates order, rad
/// or m): X_GB = X_GP * X_PF * X_FM(q) * inverse(X_BM) (inverted across reversed joints).
/// `X_GB` must hold tree.num_bodies() entries (sinew::Error if q or X_GB is too short). No heap
/// allocation.
void CalcBodyPoses(const KinematicTree& tree, std::span<const double> q, std::span<Transform> X_GB);

/// Spatial velocities V_GB = [w_GB; v_GBo], both expressed in G (rad/s, m/s; v of the body
/// frame's origin), from the poses of CalcBodyPoses and the speeds u (ModelSpec::coordinates
/// order; Ball/Free/Ellipsoid rotations are w_FM in F). `V_GB` holds num_bodies() entries.
void CalcBodyVelocities(const KinematicTree& tree, std::span<const double> q,
                        std::span<const double> u, std::span<const Transform> X_GB,
                        std::span<SpatialVec> V_GB);

/// The columns of the same map: V_GB[k * num_bodies() + b] is body b's spatial velocity when
/// u = e_k (CalcBodyVelocities with unit speed k), for every coordinate k. One joint velocity
/// matrix H_FM per joint, then rigid transport outward over the subtree of k's joint (the
/// column is zero elsewhere). `V_GB` holds num_bodies() * num_coordinates() entries. No heap
/// allocation.
void CalcBodyVelocityColumns(const KinematicTree& tree, std::span<const double> q,
                             std::span<const Transform> X_GB, std::span<SpatialVec> V_GB);

/// The same columns where they are not zero, body by body: V[tree.support_offset(b) + i] is
/// body b's spatial velocity when u = e_k with k = tree.support(b)[i] (any coordinate not in
/// tree.support(b) leaves b at rest). `V` holds tree.support_offset(tree.num_bodies())
/// entries; a body's columns are contiguous. Only the outboard bodies of `joints` (indices
/// into tree.joints(), increasing, each joint's inboard joints listed too, as
/// ListJointsToBodies gives them) are filled, the others left as they are; empty: every body.
/// No heap allocation.
void CalcSupportVelocityColumns(const KinematicTree& tree, std::span<const double> q,
                                std::span<const Transform> X_GB, std::span<SpatialVec> V,
                                std::span<const int> joints = {});

/// The tree joints (indices into tree.joints(), increasing) between ground and any of `bodies`
/// (body indices): what places those bodies and every body inboard of them.
std::vector<int> ListJointsToBodies(const KinematicTree& tree, std::span<const int> bodies);

/// Ground position (m) of each body's mass centre.
std::vector<Vec3> CalcMassCenterLocations(const model::ModelSpec& spec,
                                          std::span<const Transform> X_GB);

/// Ground position (m) of each marker of the model.
std::vector<Vec3> CalcMarkerLocations(const model::ModelSpec& spec,
                                      std::span<const Transform> X_GB);

/// Ground position (m) of a station p_BS (in body B) and its velocity in G (m/s).
inline Vec3 CalcStationLocation(const Transform& X_GB, const Vec3& p_BS) { return X_GB * p_BS; }
inline Vec3 CalcStationVelocity(const Transform& X_GB, const SpatialVec& V_GB, const Vec3& p_BS) {
  return V_GB.tail<3>() + V_GB.head<3>().cross(X_GB.R * p_BS);
}

}  // namespace sinew::kinematics

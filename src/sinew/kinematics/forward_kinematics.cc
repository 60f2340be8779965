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

// Where joint t's relative motion is mapped into G at a pose: the inboard joint frame's
// orientation, the lever from the outboard joint frame's origin to the outboard body's, and,
// for a reversed joint, X_MF.
struct JointFramesInG {
  Transform X_MF;  // reversed joints only
  Mat3 R_GJ1;
  Vec3 p_J2O_G;
};

JointFramesInG CalcJointFramesInG(const TreeJoint& t, std::span<const double> qs,
                                  std::span<const Transform> X_GB) {
  JointFramesInG f;
  if (t.reversed) f.X_MF = t.model->CalcX_FM(qs).Inverse();
  const Transform& X_GO = X_GB[t.outboard];
  f.R_GJ1 = (X_GB[t.inboard] * t.X_IJ).R;
  f.p_J2O_G = X_GO.p - X_GO * t.X_JO.Inverse().p;  // from J2's origin to O's, in G
  return f;
}

// What a relative velocity V_FM (in F) across joint t adds to its outboard body's spatial
// velocity, in G: the angular velocity across the joint, and the velocity of the outboard
// origin it causes.
SpatialVec MapJointVelocityToG(const TreeJoint& t, const JointFramesInG& f,
                               const SpatialVec& V_FM) {
  Vec3 w_rel = V_FM.head<3>(), v_rel = V_FM.tail<3>();
  // Relative motion of the outboard joint frame J2 in the inboard one J1, in J1. Reversed:
  // the motion of F in M: w_MF = -R_MF w_FM, v_MF = w_MF x p_MF - R_MF v_FM.
  if (t.reversed) {
    w_rel = -(f.X_MF.R * w_rel);
    v_rel = w_rel.cross(f.X_MF.p) - f.X_MF.R * v_rel;
  }
  SpatialVec V;
  V.head<3>() = f.R_GJ1 * w_rel;
  V.tail<3>() = f.R_GJ1 * v_rel + V.head<3>().cross(f.p_J2O_G);
  return V;
}

// What joint t's own motion (its speeds us at its coordinates qs) adds to its outboard body's
// spatial velocity, in G.
SpatialVec CalcJointTwistInG(const TreeJoint& t, std::span<const double> qs,
                             std::span<const double> us, std::span<const Transform> X_GB) {
  return MapJointVelocityToG(t, CalcJointFramesInG(t, qs, X_GB), t.model->CalcV_FM(qs, us));
}

// The twists in G of joint t's unit speeds, one per coordinate (into twists[0 .. nq)): the
// joint's velocity map H_FM and frames formed once for all of them.
void CalcJointColumnsInG(const TreeJoint& t, std::span<const double> q,
                         std::span<const Transform> X_GB, std::array<SpatialVec, 6>& twists) {
  const std::array<double, 6> q_local = Gather(t, q);
  const std::span<const double> qs(q_local.data(), t.nq);
  if (t.nq == 0) return;
  const JointFramesInG frames = CalcJointFramesInG(t, qs, X_GB);
  const Mat6X H_FM = t.model->CalcH_FM(qs);
  for (int i = 0; i < t.nq; ++i) {
    twists[static_cast<size_t>(i)] = MapJointVelocityToG(t, frames, H_FM.col(i));
  }
}

// A body's velocity carried rigidly from the inboard origin to the outboard one.
SpatialVec TransportVelocity(const TreeJoint& t, std::span<const Transform> X_GB,
                             const SpatialVec& V_GI) {
  SpatialVec V;
  V.head<3>() = V_GI.head<3>();
  V.tail<3>() = V_GI.tail<3>() + V_GI.head<3>().cross(X_GB[t.outboard].p - X_GB[t.inboard].p);
  return V;
}

// The outboard body's velocity: the inboard body's, carried rigidly to the outboard origin,
// plus the joint's own twist.
void AddInboardVelocity(const TreeJoint& t, std::span<const Transform> X_GB,
                        std::span<SpatialVec> V_GB) {
  V_GB[t.outboard] += TransportVelocity(t, X_GB, V_GB[t.inboard]);
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
  if (q.size() < nc || X_GB.size() < nb || V_GB.size() < nb * nc) {
    throw Error("CalcBodyVelocityColumns: q, X_GB or V_GB is too short for the model");
  }
  // Column k is zero but on the subtree of k's joint: each joint carries outward only the
  // columns that move its inboard body (its support), then adds its own coordinates' twists.
  for (size_t i = 0; i < nb * nc; ++i) V_GB[i].setZero();
  std::array<SpatialVec, 6> twists;
  for (const TreeJoint& t : tree.joints()) {
    const size_t in = static_cast<size_t>(t.inboard), out = static_cast<size_t>(t.outboard);
    for (const int k : tree.support(t.inboard)) {
      const size_t column = static_cast<size_t>(k) * nb;
      V_GB[column + out] = TransportVelocity(t, X_GB, V_GB[column + in]);
    }
    CalcJointColumnsInG(t, q, X_GB, twists);
    for (int i = 0; i < t.nq; ++i) {
      V_GB[static_cast<size_t>(t.q_index[static_cast<size_t>(i)]) * nb + out] =
          twists[static_cast<size_t>(i)];
    }
  }
}

void CalcSupportVelocityColumns(const KinematicTree& tree, std::span<const double> q,
                                std::span<const Transform> X_GB, std::span<SpatialVec> V,
                                std::span<const int> joints) {
  const size_t nb = static_cast<size_t>(tree.num_bodies());
  if (q.size() < static_cast<size_t>(tree.num_coordinates()) || X_GB.size() < nb ||
      V.size() < static_cast<size_t>(tree.support_offset(tree.num_bodies()))) {
    throw Error("CalcSupportVelocityColumns: q, X_GB or V is too short for the model");
  }
  const size_t num_joints = joints.empty() ? tree.joints().size() : joints.size();
  // The outboard body's support is the inboard body's followed by the joint's coordinates.
  std::array<SpatialVec, 6> twists;
  for (size_t j = 0; j < num_joints; ++j) {
    const TreeJoint& t = tree.joints()[joints.empty() ? j : static_cast<size_t>(joints[j])];
    const size_t in = static_cast<size_t>(tree.support_offset(t.inboard));
    const size_t out = static_cast<size_t>(tree.support_offset(t.outboard));
    const size_t inherited = tree.support(t.inboard).size();
    for (size_t i = 0; i < inherited; ++i) V[out + i] = TransportVelocity(t, X_GB, V[in + i]);
    CalcJointColumnsInG(t, q, X_GB, twists);
    for (int i = 0; i < t.nq; ++i) {
      V[out + inherited + static_cast<size_t>(i)] = twists[static_cast<size_t>(i)];
    }
  }
}

std::vector<int> ListJointsToBodies(const KinematicTree& tree, std::span<const int> bodies) {
  std::vector<bool> wanted(static_cast<size_t>(tree.num_bodies()), false);
  for (const int b : bodies) wanted.at(static_cast<size_t>(b)) = true;
  // Outermost joints first: a wanted body wants its inboard body.
  std::vector<int> joints;
  for (size_t j = tree.joints().size(); j-- > 0;) {
    const TreeJoint& t = tree.joints()[j];
    if (!wanted[static_cast<size_t>(t.outboard)]) continue;
    wanted[static_cast<size_t>(t.inboard)] = true;
    joints.push_back(static_cast<int>(j));
  }
  return {joints.rbegin(), joints.rend()};
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

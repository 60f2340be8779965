#include <sinew/common/error.h>
#include <sinew/kinematics/joint_tree_order.h>
#include <sinew/kinematics/kinematic_tree.h>

#include <array>
#include <string>
#include <vector>

namespace sinew::kinematics {

KinematicTree::KinematicTree(const model::ModelSpec& spec)
    : num_bodies_(static_cast<int>(spec.bodies.size())),
      num_coordinates_(static_cast<int>(spec.coordinates.size())) {
  if (num_bodies_ == 0) throw Error(SourceLocation{spec.file, 0}, "", "model has no ground body");
  for (const model::CoordinateSpec& c : spec.coordinates) {
    default_q_.push_back(c.default_value);
    default_u_.push_back(c.default_speed_value);
  }
  const int num_joints = static_cast<int>(spec.joints.size());
  for (int j = 0; j < num_joints; ++j) {
    const model::JointSpec& joint = spec.joints[j];
    const std::string component = joint.path.empty() ? joint.name : joint.path;
    for (int b : {joint.parent_body, joint.child_body}) {
      if (b < 0 || b >= num_bodies_) throw Error(joint.where, component, "joint body out of range");
    }
    if (joint.parent_body == joint.child_body) {
      throw Error(joint.where, component, "joint connects a body to itself");
    }
    for (int c : joint.coordinates) {
      if (c < 0 || c >= num_coordinates_) {
        throw Error(joint.where, component, "joint coordinate out of range");
      }
    }
    if (joint.coordinates.size() > 6)
      throw Error(joint.where, component, "more than 6 coordinates");
  }

  // Place bodies outward from ground (OrderJointTree), then make each placing joint's model.
  std::vector<std::array<int, 2>> bodies_of_joint;
  for (const model::JointSpec& joint : spec.joints) {
    bodies_of_joint.push_back({joint.parent_body, joint.child_body});
  }
  const JointTreeOrder order = OrderJointTree(num_bodies_, bodies_of_joint);
  for (int j : order.order) {
    const model::JointSpec& joint = spec.joints[j];
    TreeJoint t;
    t.joint = j;
    t.reversed = order.reversed[j];
    t.inboard = t.reversed ? joint.child_body : joint.parent_body;
    t.outboard = t.reversed ? joint.parent_body : joint.child_body;
    t.X_IJ = t.reversed ? joint.X_BM : joint.X_PF;
    t.X_JO = t.reversed ? joint.X_PF.Inverse() : joint.X_BM.Inverse();
    t.nq = static_cast<int>(joint.coordinates.size());
    for (int k = 0; k < t.nq; ++k) t.q_index[k] = joint.coordinates[k];
    t.model = MakeJointModel(spec, j);
    if (t.model->nq() != t.nq) {
      throw Error(joint.where, joint.path, "joint model and spec disagree on coordinates");
    }
    joints_.push_back(std::move(t));
  }
  for (int j = 0; j < num_joints; ++j) {
    if (order.loop[j]) {
      MakeJointModel(spec, j);  // still a joint Sinew must be able to model
      loop_joints_.push_back(j);
    }
  }
  const std::vector<bool>& placed = order.placed;
  for (int b = 0; b < num_bodies_; ++b) {
    if (!placed[b]) {
      const model::BodySpec& body = spec.bodies[b];
      throw Error(body.where, body.path.empty() ? body.name : body.path,
                  "body is not connected to ground by any joint");
    }
  }

  // Each body's support: its inboard body's, then its joint's coordinates (tree order places
  // the inboard body first); laid end to end in body order.
  std::vector<std::vector<int>> support(static_cast<size_t>(num_bodies_));
  for (const TreeJoint& t : joints_) {
    std::vector<int>& s = support[static_cast<size_t>(t.outboard)];
    s = support[static_cast<size_t>(t.inboard)];
    s.insert(s.end(), t.q_index.begin(), t.q_index.begin() + t.nq);
  }
  support_offsets_.push_back(0);
  for (const std::vector<int>& s : support) {
    support_.insert(support_.end(), s.begin(), s.end());
    support_offsets_.push_back(static_cast<int>(support_.size()));
  }
}

}  // namespace sinew::kinematics

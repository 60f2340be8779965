#include <sinew/kinematics/joint_tree_order.h>

namespace sinew::kinematics {

JointTreeOrder OrderJointTree(int num_bodies, std::span<const std::array<int, 2>> joints) {
  const int num_joints = static_cast<int>(joints.size());
  JointTreeOrder tree;
  tree.reversed.assign(num_joints, false);
  tree.loop.assign(num_joints, false);
  tree.joint_of_body.assign(num_bodies, -1);
  tree.placed.assign(num_bodies, false);
  if (num_bodies > 0) tree.placed[0] = true;
  std::vector<bool> used(num_joints, false);
  for (bool progress = true; progress;) {
    progress = false;
    for (int j = 0; j < num_joints; ++j) {
      if (used[j]) continue;
      const auto [parent, child] = joints[j];
      if (tree.placed[parent] == tree.placed[child]) continue;
      tree.reversed[j] = tree.placed[child];
      const int outboard = tree.reversed[j] ? parent : child;
      tree.placed[outboard] = true;
      tree.joint_of_body[outboard] = j;
      tree.order.push_back(j);
      used[j] = true;
      progress = true;
    }
  }
  for (int j = 0; j < num_joints; ++j) {
    tree.loop[j] = !used[j] && tree.placed[joints[j][0]] && tree.placed[joints[j][1]];
  }
  return tree;
}

}  // namespace sinew::kinematics

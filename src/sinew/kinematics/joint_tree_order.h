// The order in which joints place bodies outward from ground: the one tree walk shared by the
// kinematics (KinematicTree, from a ModelSpec) and the engine (engine::System::Finalize).
#pragma once

#include <array>
#include <span>
#include <vector>

namespace sinew::kinematics {

/// The result of OrderJointTree.
struct JointTreeOrder {
  std::vector<int> order;          ///< joints that place a body, in placement order
  std::vector<bool> reversed;      ///< per joint: places its parent body from its child
  std::vector<bool> loop;          ///< per joint: both bodies placed by others (closes a loop)
  std::vector<int> joint_of_body;  ///< per body: the joint that places it (-1: ground, unplaced)
  std::vector<bool> placed;        ///< per body: reached from ground (body 0)
};

/// Walks joints (parent body, child body) outward from body 0: a joint with exactly one placed
/// body places the other (reversed when that is its parent); a joint whose two bodies are
/// placed by others closes a loop. Bodies no joint reaches stay unplaced (the caller reports
/// them). Body indices must be in [0, num_bodies).
JointTreeOrder OrderJointTree(int num_bodies, std::span<const std::array<int, 2>> joints);

}  // namespace sinew::kinematics

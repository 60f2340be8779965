// The joint tree of a model, compiled once from its ModelSpec for forward kinematics: the order
// in which joints place bodies outward from ground, each joint's model and fixed frames.
#pragma once

#include <sinew/kinematics/joint_model.h>
#include <sinew/model/model_spec.h>

#include <array>
#include <memory>
#include <span>
#include <vector>

namespace sinew::kinematics {

/// One joint of the tree, in placement order: it places body `outboard` from body `inboard`.
/// Forward joints have inboard = the joint's parent body; a joint whose child body is nearer to
/// ground (OpenSim 4 reverses such joints, as 3.x `reverse` did) is `reversed`: X_FM(q) still
/// maps the parent frame F to the child frame M, but it is used inverted.
struct TreeJoint {
  int joint = model::kNone;     ///< Index into ModelSpec::joints.
  int inboard = model::kNone;   ///< Body already placed.
  int outboard = model::kNone;  ///< Body this joint places.
  bool reversed = false;
  Transform X_IJ;  ///< The joint frame on the inboard body (X_PF, or X_BM if reversed).
  Transform X_JO;  ///< Outboard body in its joint frame (inverse X_BM, or inverse X_PF).
  int nq = 0;
  std::array<int, 6> q_index{};  ///< Indices into ModelSpec::coordinates, joint order.
  std::shared_ptr<const JointModel> model;
};

/// A ModelSpec's joint tree. Immutable; safe to share between threads.
class KinematicTree {
 public:
  /// Builds the tree. Throws sinew::Error (file, line, component) for a joint that cannot be
  /// modelled or a body no joint connects to ground. A joint whose two bodies are already
  /// placed closes a loop: it does not place anything and is listed in loop_joints() (OpenSim
  /// likewise cuts such a joint, splitting its child body with a weld constraint, so it only
  /// acts when the model is assembled or simulated).
  explicit KinematicTree(const model::ModelSpec& spec);

  int num_bodies() const { return num_bodies_; }
  int num_coordinates() const { return num_coordinates_; }
  /// Joints in placement order (every body but ground placed once).
  const std::vector<TreeJoint>& joints() const { return joints_; }

  /// Joints (indices into ModelSpec::joints) that close kinematic loops.
  const std::vector<int>& loop_joints() const { return loop_joints_; }

  /// The coordinates whose speeds move body b: those of the tree joints between ground and b,
  /// inboard joints first, each joint's in its own order (empty for ground). Every other
  /// coordinate's speed leaves b at rest (loop joints' coordinates move no body here).
  std::span<const int> support(int b) const {
    return {support_.data() + support_offsets_[static_cast<size_t>(b)],
            static_cast<size_t>(support_offsets_[static_cast<size_t>(b) + 1] -
                                support_offsets_[static_cast<size_t>(b)])};
  }
  /// Where body b's support starts when every body's support is laid end to end in body order;
  /// support_offset(num_bodies()) is the length of them all. support(b) of the outboard body of
  /// a tree joint is its inboard body's support followed by the joint's coordinates.
  int support_offset(int b) const { return support_offsets_[static_cast<size_t>(b)]; }

  /// Coordinate default values (rad or m), in ModelSpec::coordinates order.
  const std::vector<double>& default_q() const { return default_q_; }
  /// Coordinate default speeds, in ModelSpec::coordinates order.
  const std::vector<double>& default_u() const { return default_u_; }

 private:
  int num_bodies_ = 0;
  int num_coordinates_ = 0;
  std::vector<TreeJoint> joints_;
  std::vector<int> loop_joints_;
  std::vector<int> support_, support_offsets_;
  std::vector<double> default_q_, default_u_;
};

}  // namespace sinew::kinematics

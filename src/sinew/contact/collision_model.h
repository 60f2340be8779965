// Collision shapes of a parsed model (the seed's EnableCollision): a cylinder along every
// segment from a body's frame to each joint frame on it, and two collision families that
// alternate with depth in the joint tree so that a body never collides with its parent or
// its children.
#pragma once

#include <sinew/math/types.h>
#include <sinew/model/model_spec.h>

#include <vector>

namespace sinew::contact {

/// How contact is to be treated in a system (the seed's two methods): kNsc non-smooth
/// (complementarity), kSmc smooth (penalty).
enum class ContactMethod {
  kNsc,
  kSmc,
  // The seed's spellings, so that programs written against its API compile unchanged.
  NSC = kNsc,
  SMC = kSmc,
};

/// A capsule-like cylinder fixed to a body, from `p_B_start` to `p_B_end` (in B, metres).
struct CollisionCylinder {
  int body = model::kGroundIndex;
  Vec3 p_B_start = Vec3::Zero();
  Vec3 p_B_end = Vec3::Zero();
  double radius = 0.0;  ///< m
};

/// Shapes and families of a model. Bodies collide only when their families are equal.
struct CollisionModel {
  std::vector<CollisionCylinder> shapes;
  std::vector<int> family;  ///< Per spec body (ground: 0, no shapes).

  /// True when shapes of bodies `a` and `b` may touch (different bodies, same family).
  bool CanCollide(int a, int b) const {
    return a != b && a != model::kGroundIndex && b != model::kGroundIndex && family[a] == family[b];
  }
};

/// Builds the collision model of `spec`: bodies at odd tree depth (`depth` per body, ground 0)
/// get `family_1`, at even depth `family_2`. The cylinder radius is 10% of the median segment
/// length of the model (at least 1 mm). Segments shorter than 1 mm get no shape.
CollisionModel BuildCollisionModel(const model::ModelSpec& spec, const std::vector<int>& depth,
                                   int family_1, int family_2);

}  // namespace sinew::contact

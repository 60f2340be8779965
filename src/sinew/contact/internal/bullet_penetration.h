// Whether two convex Bullet shapes (each grown by its margin) overlap, and by how much: Bullet's
// closest points (btGjkPairDetector: GJK on the shapes' cores, and EPA once the cores overlap),
// or, when neither shape has a margin (the envelope is 0 and neither is a sphere, whose radius is
// its margin), EPA directly. Then the cores are the shapes: GJK's distance is of no use (any
// positive one means no contact), and Bullet's pair detector would run two GJKs (libccd's
// intersection test, then its own) before the GJK and EPA of btGjkEpaSolver2::Penetration, which
// alone decide. The direct call is the one Bullet makes (same guess, same transforms shifted to
// their midpoint), so its depth, normal and point are Bullet's; where Bullet would repair a
// result (EPA or GJK failing, a normal EPA got backwards) the pair detector runs as before.
// Private to the contact layer (it includes Bullet).
#pragma once

#include <BulletCollision/CollisionShapes/btConvexShape.h>

namespace sinew::contact {

/// Bullet's answer for an overlapping pair: `distance` < 0 (minus the overlap of the shapes
/// grown by their margins), `normal_on_B` (unit, from B towards A) and `point_on_B` (on B's
/// grown surface), in the frame of the transforms.
struct BulletOverlap {
  btVector3 normal_on_B;
  btVector3 point_on_B;
  btScalar distance = 0.0;
};

/// True, with `out` set, when A at X_A and B at X_B overlap (Bullet's distance < 0).
bool BulletPenetration(const btConvexShape* A, const btTransform& X_A, const btConvexShape* B,
                       const btTransform& X_B, BulletOverlap& out);

}  // namespace sinew::contact

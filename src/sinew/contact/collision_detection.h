// Collision detection between the seed's collision cylinders (contact::CollisionModel) and an
// optional ground plane, through Bullet's collision library: its AABB test as the broad phase,
// GJK/EPA as the narrow phase between cylinders, and the shapes' support vertices against the
// plane (what Bullet's convex-plane algorithm does). Stateless per query (no contact caching), so one detector
// can be shared by threads and by the stages of a Runge-Kutta step.
#pragma once

#include <sinew/contact/collision_model.h>
#include <sinew/math/transform.h>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace sinew::contact {

/// One contact between two shapes: they overlap by `depth` (m) along `n_G` (unit, in G, from
/// shape 1's body towards shape 2's body), centred at `p_G`; `radius` is the effective radius
/// of curvature of the pair (cylinder radii combined as r1 r2 / (r1 + r2), the plane's
/// infinite).
struct CollisionContact {
  int body1 = 0;
  int body2 = 0;
  Vec3 p_G = Vec3::Zero();
  Vec3 n_G = Vec3::UnitY();
  double depth = 0.0;
  double radius = 0.0;
};

/// Finds the contacts of a collision model's cylinders with each other (pairs the families
/// allow, CollisionModel::CanCollide) and with a ground plane y = `ground_height` (the solid
/// below it), when given. Bodies are the model's (spec) body indices.
class CollisionDetector {
 public:
  /// Pairs of cylinders that already overlap at the rest poses `X_GB_rest` (one per body,
  /// ground first; the model's default pose), typically at the joints where segments meet, are
  /// left out, as are their bodies' pairs with nothing else: they could only push the joints
  /// apart. Empty `X_GB_rest`: every allowed pair is kept.
  CollisionDetector(const CollisionModel& model, std::optional<double> ground_height,
                    const std::vector<Transform>& X_GB_rest = {});
  ~CollisionDetector();
  CollisionDetector(const CollisionDetector&) = delete;
  CollisionDetector& operator=(const CollisionDetector&) = delete;

  /// Calls `visit` for every overlapping pair at the body poses `X_GB` (one per body, ground
  /// first). One contact point per pair (Bullet's deepest point).
  void FindContacts(const std::vector<Transform>& X_GB,
                    const std::function<void(const CollisionContact&)>& visit) const;
  /// The number of shape pairs tested (allowed by the families, plus each cylinder with the
  /// plane).
  int num_pairs() const;
  /// The number of cylinder pairs left out because they overlap at the rest poses.
  int num_excluded_at_rest() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sinew::contact

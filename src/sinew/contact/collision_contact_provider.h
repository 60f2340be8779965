// The seed's collision cylinders (and a ground plane) as an engine::ContactProvider, so that
// the NSC stepper (engine::NscIntegrator) can make them collide: `--contact nsc --collision
// [--ground-plane H]`.
#pragma once

#include <sinew/contact/collision_detection.h>
#include <sinew/contact/collision_model.h>
#include <sinew/engine/unilateral_contact.h>

#include <memory>
#include <optional>
#include <vector>

namespace sinew::contact {

/// The contact material of every shape pair (the seed's ChMaterialSurfaceNSC defaults:
/// friction 0.6, no restitution) and the envelope within which contacts are reported before
/// the shapes touch.
struct NscMaterial {
  double friction = 0.6;     ///< Coulomb coefficient (>= 0)
  double restitution = 0.0;  ///< Newton's coefficient (0 to 1)
  /// Contacts are reported while the gap is below this (m), so that the stepper stops bodies
  /// where they meet instead of letting them sink in first: the plane is queried raised by it,
  /// the pairs of cylinders with every radius inflated by half of it, and the depth reported
  /// is the detector's minus it. Exact for any cylinder on the plane and for cylinder sides
  /// meeting; where an end cap meets another cylinder only that cylinder is inflated, so the
  /// pair may end up overlapping by up to half the envelope. 0: contacts only once shapes
  /// overlap.
  double envelope = 2e-3;
};

/// Contacts of a collision model's cylinders with each other and with a ground plane y = H,
/// through a CollisionDetector. Bodies are the model's (spec) body indices, which are the
/// System's for systems the OpenSim parser builds.
class CollisionContactProvider final : public engine::ContactProvider {
 public:
  /// `X_GB_rest`: the rest poses whose overlapping cylinder pairs are left out (see
  /// CollisionDetector). Throws sinew::Error for a bad material.
  CollisionContactProvider(const CollisionModel& model, std::optional<double> ground_height,
                           const NscMaterial& material,
                           const std::vector<Transform>& X_GB_rest = {});

  void FindContacts(const engine::System& system, const engine::State& state,
                    std::vector<engine::UnilateralContact>& contacts) const override;

  const NscMaterial& material() const { return material_; }
  /// Shape pairs tested per query (cylinder pairs the families allow, and each cylinder with
  /// the plane).
  int num_pairs() const;

 private:
  NscMaterial material_;
  CollisionDetector pair_detector_;                    // cylinder pairs (inflated)
  std::unique_ptr<CollisionDetector> plane_detector_;  // cylinders on the raised plane

  mutable std::vector<Transform> X_GB_;  // the poses of the last query (reused)
};

/// The body poses X_GB of `state` (ground first), as CollisionDetector takes them, into `X_GB`
/// (resized; no heap use once it has its size).
void GatherBodyPoses(const engine::State& state, std::vector<Transform>& X_GB);

}  // namespace sinew::contact

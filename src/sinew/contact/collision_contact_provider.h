// The seed's collision shapes (and a ground plane) as an engine::ContactProvider, so that
// the NSC stepper (engine::NscIntegrator) can make them collide: `--contact nsc --collision
// [--ground-plane H]`.
#pragma once

#include <sinew/contact/collision_detection.h>
#include <sinew/contact/collision_model.h>
#include <sinew/engine/unilateral_contact.h>

#include <optional>
#include <utility>
#include <vector>

namespace sinew::contact {

/// The default contact material of an NSC run (the seed's ChMaterialSurfaceNSC defaults:
/// friction 0.6, no restitution), given to the shapes without a material of their own (the
/// model's entry 0), and the envelope within which contacts are reported before the shapes
/// touch.
struct NscMaterial {
  double friction = 0.6;     ///< Coulomb coefficient (>= 0)
  double restitution = 0.0;  ///< Newton's coefficient (0 to 1)
  /// Contacts are reported while the gap is below this (m), with the gap as a negative depth,
  /// so that the stepper stops bodies where they meet instead of letting them sink in first
  /// (CollisionDetector's envelope: exact for every shape pair). 0: contacts only once shapes
  /// overlap.
  double envelope = 2e-3;
};

/// Contacts of a collision model's shapes with each other and with a ground plane y = H,
/// through a CollisionDetector. Each contact has its pair's material, the two shapes' combined
/// as SMC combines them (CombineMaterials: the smaller friction, the smaller restitution);
/// shapes with the default material take the NscMaterial's. Bodies are the model's (spec) body
/// indices, which are the System's for systems the OpenSim parser builds.
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
  /// Shape pairs tested per query (the pairs the model allows, and each shape with the plane).
  int num_pairs() const;
  /// The body pairs (body1 < body2) of the tested shape pairs, sorted, each once.
  std::vector<std::pair<int, int>> BodyPairs() const { return detector_.BodyPairs(); }

 private:
  NscMaterial material_;
  CollisionDetector detector_;

  mutable std::vector<Transform> X_GB_;  // the poses of the last query (reused)
};

/// The body poses X_GB of `state` (ground first), as CollisionDetector takes them, into `X_GB`
/// (resized; no heap use once it has its size).
void GatherBodyPoses(const engine::State& state, std::vector<Transform>& X_GB);

}  // namespace sinew::contact

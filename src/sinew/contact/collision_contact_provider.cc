#include <sinew/common/error.h>
#include <sinew/contact/collision_contact_provider.h>
#include <sinew/engine/pose.h>
#include <sinew/engine/state.h>

#include <cmath>

namespace sinew::contact {
namespace {

const NscMaterial& CheckMaterial(const NscMaterial& material) {
  if (!(material.friction >= 0.0) || !std::isfinite(material.friction)) {
    throw Error("contact: NSC friction must be a finite number >= 0");
  }
  if (!(material.restitution >= 0.0 && material.restitution <= 1.0)) {
    throw Error("contact: NSC restitution must be between 0 and 1");
  }
  if (!(material.envelope >= 0.0) || !std::isfinite(material.envelope)) {
    throw Error("contact: NSC envelope must be a finite length >= 0");
  }
  return material;
}

// The model whose default material (entry 0) has the NSC material's friction and restitution.
CollisionModel WithDefaultMaterial(CollisionModel model, const NscMaterial& material) {
  if (model.materials.empty()) model.materials.resize(1);
  model.materials.front().friction = material.friction;
  model.materials.front().restitution = material.restitution;
  return model;
}

}  // namespace

CollisionContactProvider::CollisionContactProvider(const CollisionModel& model,
                                                   std::optional<double> ground_height,
                                                   const NscMaterial& material,
                                                   const std::vector<Transform>& X_GB_rest)
    : material_(CheckMaterial(material)),
      detector_(WithDefaultMaterial(model, material), ground_height, X_GB_rest,
                material.envelope) {}

int CollisionContactProvider::num_pairs() const { return detector_.num_pairs(); }

void CollisionContactProvider::FindContacts(
    const engine::System&, const engine::State& state,
    std::vector<engine::UnilateralContact>& contacts) const {
  GatherBodyPoses(state, X_GB_);
  detector_.FindContacts(X_GB_, [&](const CollisionContact& c) {
    contacts.push_back({c.body1, c.body2, c.p_G, c.n_G, c.depth, c.material.friction,
                        c.material.restitution});
  });
}

void GatherBodyPoses(const engine::State& state, std::vector<Transform>& X_GB) {
  X_GB.resize(state.bodies.size());
  for (size_t b = 0; b < state.bodies.size(); ++b) X_GB[b] = engine::PoseOf(state.bodies[b]);
}

}  // namespace sinew::contact

#include <sinew/common/error.h>
#include <sinew/contact/collision_contact_provider.h>
#include <sinew/engine/pose.h>
#include <sinew/engine/state.h>

#include <cmath>
#include <memory>

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

// The model with every radius inflated by half the envelope (for the pairs of cylinders).
CollisionModel Inflate(CollisionModel model, double envelope) {
  for (CollisionCylinder& shape : model.shapes) shape.radius += 0.5 * envelope;
  return model;
}

// The model with every body in a family of its own: no pair may collide, only the plane.
CollisionModel WithoutPairs(CollisionModel model) {
  for (size_t b = 0; b < model.family.size(); ++b) model.family[b] = static_cast<int>(b);
  return model;
}

}  // namespace

CollisionContactProvider::CollisionContactProvider(const CollisionModel& model,
                                                   std::optional<double> ground_height,
                                                   const NscMaterial& material,
                                                   const std::vector<Transform>& X_GB_rest)
    : material_(CheckMaterial(material)),
      pair_detector_(Inflate(model, material.envelope), std::nullopt, X_GB_rest) {
  if (ground_height) {
    plane_detector_ = std::make_unique<CollisionDetector>(WithoutPairs(model),
                                                          *ground_height + material.envelope);
  }
}

int CollisionContactProvider::num_pairs() const {
  return pair_detector_.num_pairs() + (plane_detector_ ? plane_detector_->num_pairs() : 0);
}

void CollisionContactProvider::FindContacts(
    const engine::System&, const engine::State& state,
    std::vector<engine::UnilateralContact>& contacts) const {
  GatherBodyPoses(state, X_GB_);
  const double envelope = material_.envelope;
  // Depths come back deeper by the envelope. Between inflated cylinders the midway point of the
  // overlap is where it is without inflation; on the raised plane it is half the envelope
  // above the midway point of the real plane.
  auto add = [&](const CollisionContact& c, const Vec3& p_G) {
    contacts.push_back({c.body1, c.body2, p_G, c.n_G, c.depth - envelope, material_.friction,
                        material_.restitution});
  };
  pair_detector_.FindContacts(X_GB_, [&](const CollisionContact& c) { add(c, c.p_G); });
  if (plane_detector_) {
    plane_detector_->FindContacts(
        X_GB_, [&](const CollisionContact& c) { add(c, c.p_G - 0.5 * envelope * c.n_G); });
  }
}

void GatherBodyPoses(const engine::State& state, std::vector<Transform>& X_GB) {
  X_GB.resize(state.bodies.size());
  for (size_t b = 0; b < state.bodies.size(); ++b) X_GB[b] = engine::PoseOf(state.bodies[b]);
}

}  // namespace sinew::contact

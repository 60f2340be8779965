// A contact provider for the NSC tests: spheres fixed to bodies, against a ground plane y = 0
// (the solid below) and against each other, reported within an envelope (so the stepper stops
// them where they meet). Written from the closed-form geometry of spheres, independently of
// the collision detector.
#pragma once

#include <sinew/engine/state.h>
#include <sinew/engine/system.h>
#include <sinew/engine/unilateral_contact.h>

#include <vector>

namespace sinew::testing {

struct TestSphere {
  int body = 1;
  Vec3 p_BC = Vec3::Zero();  ///< centre in the body frame
  double radius = 0.1;
};

class SphereContactProvider final : public engine::ContactProvider {
 public:
  SphereContactProvider(std::vector<TestSphere> spheres, bool ground, double friction,
                        double restitution, double envelope)
      : spheres_(std::move(spheres)),
        ground_(ground),
        friction_(friction),
        restitution_(restitution),
        envelope_(envelope) {}

  void FindContacts(const engine::System&, const engine::State& state,
                    std::vector<engine::UnilateralContact>& contacts) const override {
    std::vector<Vec3>& centres = centres_;  // reused: no heap use once sized
    centres.clear();
    for (const TestSphere& s : spheres_) {
      const engine::BodyState& b = state.bodies[s.body];
      centres.push_back(b.p_GB + b.quat_GB * s.p_BC);
    }
    for (size_t i = 0; i < spheres_.size(); ++i) {
      const double r = spheres_[i].radius;
      if (ground_ && centres[i].y() - r < envelope_) {
        // Ground (body1) to the sphere (body2): the normal is +y, the point midway between the
        // sphere's lowest point and the floor below it (UnilateralContact's convention).
        const double gap = centres[i].y() - r;
        contacts.push_back({0, spheres_[i].body, centres[i] - (r + 0.5 * gap) * Vec3::UnitY(),
                            Vec3::UnitY(), -gap, friction_, restitution_});
      }
      for (size_t j = i + 1; j < spheres_.size(); ++j) {
        const Vec3 d = centres[j] - centres[i];
        const double gap = d.norm() - r - spheres_[j].radius;
        if (gap >= envelope_ || spheres_[i].body == spheres_[j].body) continue;
        const Vec3 n = d.normalized();
        contacts.push_back({spheres_[i].body, spheres_[j].body, centres[i] + (r + 0.5 * gap) * n, n,
                            -gap, friction_, restitution_});
      }
    }
  }

 private:
  mutable std::vector<Vec3> centres_;
  std::vector<TestSphere> spheres_;
  bool ground_;
  double friction_, restitution_, envelope_;
};

}  // namespace sinew::testing

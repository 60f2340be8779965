// SMC, the seed's smooth (penalty) contact method, as a force element over the contacts of a
// CollisionDetector: Hertz normal force with restitution through its damping, regularized
// Coulomb friction. docs/contact.md gives the laws.
#pragma once

#include <sinew/contact/collision_detection.h>
#include <sinew/contact/contact_force.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace sinew::contact {

/// Smooth contact between collision shapes. For a contact of depth d, effective radius R,
/// effective mass m = m1 m2 / (m1 + m2) (ground's mass infinite), approach speed v_n and slip
/// velocity v_t, with the pair's material:
/// - kn > 0: f_n = sqrt(R d) (kn d + gn m v_n);
/// - otherwise Hertz from the effective modulus E*: f_n = 4/3 E* sqrt(R d) d + c v_n with
///   c = 2 sqrt(5/6) b sqrt(2 E* sqrt(R d) m), b = -ln(e) / sqrt(ln(e)^2 + pi^2) (restitution e);
/// f_n is never negative; friction -u f_n v_t / sqrt(|v_t|^2 + v_s^2) with the slip speed
/// v_s = `slip_speed`, or u f_n / gt when gt > 0 (so gt is the slope at zero slip).
/// With the pair's kt > 0 friction is a tangential spring instead (Cundall and Strack's, as
/// Chrono's SMC with a contact history): f_t = -k_t xi - gt v_t with k_t = kt sqrt(R d), capped
/// at u f_n along its own direction, xi the tangential displacement of the two bodies' points
/// since the contact began (kept from step to step, HasDiscreteData; a slipping contact's
/// spring stays stretched to the cap). A contact that began inside the current step has the
/// regularized friction until the step ends.
/// Potential energy: the Hertz elastic part, 2/5 f_el d per contact, and 1/2 k_t |xi|^2.
class SmoothCollisionForce final : public ContactForce {
 public:
  /// `detector`'s bodies are engine body indices; `masses` per engine body (ground first,
  /// its entry ignored); `groups` the bodies reported; `pairs` the body pairs whose active
  /// contacts are counted (labels "<body1>-<body2>"). `tangential_springs`: some pair's
  /// material has kt > 0, so the contacts' tangential displacements are kept.
  SmoothCollisionForce(std::string name, std::shared_ptr<const CollisionDetector> detector,
                       std::vector<double> masses, double slip_speed,
                       std::vector<RecordGroup> groups, std::vector<PairGroup> pairs,
                       bool tangential_springs = false);

  double VisitContacts(const engine::State& state, ContactSink& sink) const override;
  double slip_speed() const { return slip_speed_; }

  /// How far (m) a contact's point may be from where the body's point of a kept contact of the
  /// same two bodies has moved since the last step, for the two to be one contact: the nearest
  /// such kept contact within this distance carries its displacement on.
  static constexpr double kHistoryMatchDistance = 0.01;
  bool HasDiscreteData() const override { return tangential_springs_; }
  /// Every contact with kt > 0 that pushes: its points on both bodies and its displacement,
  /// shortened so that the spring alone pulls at most u f_n; and every contact found, which an
  /// evaluation at exactly these poses (the next step's first) uses without searching again.
  std::shared_ptr<const engine::DiscreteData> UpdateDiscreteData(
      const engine::ForceContext& context) const override;

  /// The contacts' load Jacobians for implicit integration, over Support()'s bodies. D = df/dv
  /// is exact: each force depends on the velocities only through the relative velocity at its
  /// point. K = df/dx keeps the dominant part, the depth's: the normal force's slope with the
  /// depth (and the friction's through it) along the normal; how the contact's point, normal
  /// and levers move with the bodies is left out (terms of order f / R against f' = 3 f / 2d).
  bool CalcLoadJacobians(const engine::ForceContext& context, Eigen::Ref<MatX> K,
                         Eigen::Ref<MatX> D) const override;

 private:
  // One contact's law at the relative velocity v_G (body 2's point less body 1's): the force on
  // body 2 at c.p_G (body 1 takes its opposite), its elastic energy, and when `slopes`, its
  // derivatives with respect to v_G (D_rel) and to the displacement of body 2's point relative
  // to body 1's through the depth (K_rel).
  // `xi`: the contact's tangential displacement when it has a spring (kt > 0, kept from an
  // earlier step); null: the regularized friction.
  struct Response {
    Vec3 f = Vec3::Zero();
    double energy = 0.0;
    double normal = 0.0;  // f_n
    Mat3 D_rel = Mat3::Zero(), K_rel = Mat3::Zero();
  };
  Response Respond(const CollisionContact& c, const Vec3& v_G, const Vec3* xi, bool slopes) const;
  // A contact's normal force as Respond finds it: its normal and depth, sqrt(R d), f_n, the
  // Coulomb limit u f_n, and f_n's slopes with the approach speed (-damping) and the depth.
  struct Normal {
    Vec3 n;
    double d, sqrt_Rd, force, friction, damping, dfn_dd;
  };
  // Respond's friction when the pair's kt > 0, into `r`.
  static Response RespondWithSpring(const PairMaterial& m, const Normal& normal,
                                    const Vec3& v_tangent, const Vec3& xi, bool slopes, Response r);
  // Body 2's point velocity less body 1's at the contact.
  static Vec3 RelativeVelocity(const engine::State& state, const CollisionContact& c);
  // The contacts kept at the last step's end (UpdateDiscreteData).
  struct History;
  // Contact c's tangential displacement at poses X_GB: a kept contact's (the nearest within
  // kHistoryMatchDistance) plus how far its two points have moved apart since, in the tangent
  // plane; none for kt = 0 or a contact that began after the last step.
  static std::optional<Vec3> TangentialDisplacement(const History* history,
                                                    const std::vector<Transform>& X_GB,
                                                    const CollisionContact& c);
  const History* FindHistory(const engine::State& state) const;
  // Calls `visit` for every contact at poses X_GB: the history's own contacts when it was made
  // at exactly these poses (a step's start is the last step's end, where UpdateDiscreteData
  // searched), else the detector's.
  void ForEachContact(const History* history, const std::vector<Transform>& X_GB,
                      const std::function<void(const CollisionContact&)>& visit) const;

  std::shared_ptr<const CollisionDetector> detector_;
  std::vector<double> masses_;
  double slip_speed_;
  bool tangential_springs_;
};

}  // namespace sinew::contact

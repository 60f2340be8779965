#include <sinew/contact/smooth_collision_force.h>
#include <sinew/engine/pose.h>
#include <sinew/engine/state.h>

#include <cmath>
#include <limits>
#include <utility>

namespace sinew::contact {
namespace {

// m1 m2 / (m1 + m2), ground (body 0) and massless bodies counting as infinitely heavy.
double EffectiveMass(double m1, double m2) {
  if (!(m1 > 0.0)) return m2 > 0.0 ? m2 : 0.0;
  if (!(m2 > 0.0)) return m1;
  return m1 * m2 / (m1 + m2);
}

// The damping ratio factor of a restitution e (Chrono's and Tsuji's): -ln(e) / sqrt(ln(e)^2 +
// pi^2), 1 for e = 0, 0 for e = 1.
double DampingFactor(double restitution) {
  if (!(restitution > 0.0)) return 1.0;
  const double l = std::log(restitution);
  return -l / std::sqrt(l * l + M_PI * M_PI);
}

}  // namespace

SmoothCollisionForce::SmoothCollisionForce(std::string name,
                                           std::shared_ptr<const CollisionDetector> detector,
                                           std::vector<double> masses, double slip_speed,
                                           std::vector<RecordGroup> groups,
                                           std::vector<PairGroup> pairs)
    : ContactForce(std::move(name), std::move(groups), std::move(pairs)),
      detector_(std::move(detector)),
      masses_(std::move(masses)),
      slip_speed_(slip_speed) {}

double SmoothCollisionForce::VisitContacts(const engine::State& state, ContactSink& sink) const {
  // Per-thread scratch: no allocation per evaluation once grown.
  thread_local std::vector<Transform> X_GB;
  X_GB.resize(state.bodies.size());
  for (size_t b = 0; b < state.bodies.size(); ++b) X_GB[b] = engine::PoseOf(state.bodies[b]);
  // The visitor captures one reference, so std::function holds it without the heap
  // (EvaluationAllocationTest.SkeletonOnTheGroundStepsWithoutHeapUse).
  struct Visit {
    const SmoothCollisionForce* force;
    const engine::State* state;
    ContactSink* sink;
    double energy;
  } visit{this, &state, &sink, 0.0};
  detector_->FindContacts(X_GB, [&visit](const CollisionContact& c) {
    visit.energy += visit.force->ApplyContact(*visit.state, c, *visit.sink);
  });
  return visit.energy;
}

double SmoothCollisionForce::ApplyContact(const engine::State& state, const CollisionContact& c,
                                          ContactSink& sink) const {
  const PairMaterial& m = c.material;
  const double d = c.depth;
  const double sqrt_Rd = std::sqrt(c.radius * d);
  const double mass =
      EffectiveMass(c.body1 == 0 ? 0.0 : masses_[c.body1], c.body2 == 0 ? 0.0 : masses_[c.body2]);
  double f_elastic = 0.0, damping = 0.0;
  if (m.kn > 0.0) {
    f_elastic = m.kn * sqrt_Rd * d;
    damping = m.gn * mass * sqrt_Rd;
  } else {
    f_elastic = 4.0 / 3.0 * m.effective_modulus * sqrt_Rd * d;
    damping = 2.0 * std::sqrt(5.0 / 6.0) * DampingFactor(m.restitution) *
              std::sqrt(2.0 * m.effective_modulus * sqrt_Rd * mass);
  }
  // Velocity of body 2's point relative to body 1's at the contact point.
  const Vec3 v_G = engine::PointVelocity(state.bodies[c.body2], c.p_G) -
                   engine::PointVelocity(state.bodies[c.body1], c.p_G);
  const double v_normal = v_G.dot(c.n_G);
  const double f_normal = std::max(0.0, f_elastic - damping * v_normal);
  if (f_normal > 0.0) {
    const Vec3 v_tangent = v_G - v_normal * c.n_G;
    const double friction = m.friction * f_normal;
    const double v_s = m.gt > 0.0 ? friction / m.gt : slip_speed_;
    const Vec3 f_friction = -friction * v_tangent / std::sqrt(v_tangent.squaredNorm() + v_s * v_s);
    sink.Add({c.body1, c.body2, c.p_G, f_normal * c.n_G + f_friction});
  }
  return 0.4 * f_elastic * d;
}

}  // namespace sinew::contact

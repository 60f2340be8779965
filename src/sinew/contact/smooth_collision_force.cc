#include <sinew/contact/collision_contact_provider.h>
#include <sinew/contact/smooth_collision_force.h>
#include <sinew/engine/pose.h>
#include <sinew/engine/state.h>

#include <cmath>
#include <limits>
#include <optional>
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

struct SmoothCollisionForce::History final : engine::DiscreteData {
  struct Contact {
    int body1 = 0, body2 = 0;
    Vec3 p_B1 = Vec3::Zero(), p_B2 = Vec3::Zero();  // the contact point in each body's frame
    Vec3 xi_G = Vec3::Zero();                       // the tangential displacement (m, in G)
  };
  std::vector<Contact> contacts;
  // Every contact found at the poses the update saw, kt > 0 or not. The next step starts at
  // exactly those poses, so its first evaluation takes them instead of searching again.
  std::vector<Transform> X_GB;
  std::vector<CollisionContact> found;
};

namespace {

bool SamePoses(const std::vector<Transform>& a, const std::vector<Transform>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (a[i].R != b[i].R || a[i].p != b[i].p) return false;
  }
  return true;
}

}  // namespace

void SmoothCollisionForce::ForEachContact(
    const History* history, const std::vector<Transform>& X_GB,
    const std::function<void(const CollisionContact&)>& visit) const {
  if (history != nullptr && SamePoses(history->X_GB, X_GB)) {
    for (const CollisionContact& c : history->found) visit(c);
  } else {
    detector_->FindContacts(X_GB, visit);
  }
}

SmoothCollisionForce::SmoothCollisionForce(std::string name,
                                           std::shared_ptr<const CollisionDetector> detector,
                                           std::vector<double> masses, double slip_speed,
                                           std::vector<RecordGroup> groups,
                                           std::vector<PairGroup> pairs, bool tangential_springs)
    : ContactForce(std::move(name), std::move(groups), std::move(pairs)),
      detector_(std::move(detector)),
      masses_(std::move(masses)),
      slip_speed_(slip_speed),
      tangential_springs_(tangential_springs) {}

const SmoothCollisionForce::History* SmoothCollisionForce::FindHistory(
    const engine::State& state) const {
  if (!tangential_springs_) return nullptr;
  // Checked, not assumed: a State kept from another System could name an element that happens
  // to live at this one's address.
  return dynamic_cast<const History*>(engine::FindDiscreteData(state, this));
}

std::optional<Vec3> SmoothCollisionForce::TangentialDisplacement(const History* history,
                                                                 const std::vector<Transform>& X_GB,
                                                                 const CollisionContact& c) {
  if (history == nullptr || !(c.material.kt > 0.0)) return std::nullopt;
  const History::Contact* kept = nullptr;
  double nearest = kHistoryMatchDistance * kHistoryMatchDistance;
  for (const History::Contact& h : history->contacts) {
    if (h.body1 != c.body1 || h.body2 != c.body2) continue;
    const double distance = (X_GB[c.body2] * h.p_B2 - c.p_G).squaredNorm();
    if (distance <= nearest) nearest = distance, kept = &h;
  }
  if (kept == nullptr) return std::nullopt;
  const Vec3 xi = kept->xi_G + (X_GB[c.body2] * kept->p_B2 - X_GB[c.body1] * kept->p_B1);
  return xi - xi.dot(c.n_G) * c.n_G;
}

double SmoothCollisionForce::VisitContacts(const engine::State& state, ContactSink& sink) const {
  // Per-thread scratch: no allocation per evaluation once grown.
  thread_local std::vector<Transform> X_GB;
  GatherBodyPoses(state, X_GB);
  // The visitor captures one reference, so std::function holds it without the heap
  // (EvaluationAllocationTest.SkeletonOnTheGroundStepsWithoutHeapUse).
  struct Visit {
    const SmoothCollisionForce* force;
    const engine::State* state;
    ContactSink* sink;
    const History* history;
    const std::vector<Transform>* X_GB;
    double energy;
  } visit{this, &state, &sink, FindHistory(state), &X_GB, 0.0};
  ForEachContact(visit.history, X_GB, [&visit](const CollisionContact& c) {
    const std::optional<Vec3> xi = TangentialDisplacement(visit.history, *visit.X_GB, c);
    const Response r = visit.force->Respond(c, RelativeVelocity(*visit.state, c),
                                            xi ? &*xi : nullptr, /*slopes=*/false);
    visit.energy += r.energy;
    if (r.f.squaredNorm() > 0.0) visit.sink->Add({c.body1, c.body2, c.p_G, r.f});
  });
  return visit.energy;
}

Vec3 SmoothCollisionForce::RelativeVelocity(const engine::State& state, const CollisionContact& c) {
  return engine::PointVelocity(state.bodies[c.body2], c.p_G) -
         engine::PointVelocity(state.bodies[c.body1], c.p_G);
}

SmoothCollisionForce::Response SmoothCollisionForce::Respond(const CollisionContact& c,
                                                             const Vec3& v_G, const Vec3* xi,
                                                             bool slopes) const {
  const PairMaterial& m = c.material;
  const double d = c.depth;
  const double sqrt_Rd = std::sqrt(c.radius * d);
  const double mass =
      EffectiveMass(c.body1 == 0 ? 0.0 : masses_[c.body1], c.body2 == 0 ? 0.0 : masses_[c.body2]);
  // The elastic force goes as d^(3/2) in both laws, the damping coefficient as d^(1/2) (kn)
  // or d^(1/4) (Hertz).
  double f_elastic = 0.0, damping = 0.0, damping_power = 0.0;
  if (m.kn > 0.0) {
    f_elastic = m.kn * sqrt_Rd * d;
    damping = m.gn * mass * sqrt_Rd;
    damping_power = 0.5;
  } else {
    f_elastic = 4.0 / 3.0 * m.effective_modulus * sqrt_Rd * d;
    damping = 2.0 * std::sqrt(5.0 / 6.0) * DampingFactor(m.restitution) *
              std::sqrt(2.0 * m.effective_modulus * sqrt_Rd * mass);
    damping_power = 0.25;
  }
  Response r;
  r.energy = 0.4 * f_elastic * d;
  const Vec3& n = c.n_G;
  const double v_normal = v_G.dot(n);
  const double f_normal = f_elastic - damping * v_normal;
  if (!(f_normal > 0.0)) return r;  // never a pull: no force, and no slope on this side
  r.normal = f_normal;
  const Vec3 v_tangent = v_G - v_normal * n;
  const double friction = m.friction * f_normal;
  // K: body 2's point moved along +n by dx leaves the depth d - dx.
  const double dfn_dd = 1.5 * f_elastic / d - damping_power * damping / d * v_normal;
  if (xi != nullptr) {
    return RespondWithSpring(m, {n, d, sqrt_Rd, f_normal, friction, damping, dfn_dd}, v_tangent,
                             *xi, slopes, r);
  }
  const Mat3 P = Mat3::Identity() - n * n.transpose();  // onto the tangent plane
  const double v_s = m.gt > 0.0 ? friction / m.gt : slip_speed_;
  const double s = std::sqrt(v_tangent.squaredNorm() + v_s * v_s);
  r.f = f_normal * n - friction * v_tangent / s;
  if (!slopes) return r;
  // f = f_n n - u q v_t with q = f_n / s, s = sqrt(|v_t|^2 + v_s^2), v_s = u f_n / gt or fixed.
  const double dvs_dfn = m.gt > 0.0 ? m.friction / m.gt : 0.0;
  const double dq_dfn = 1.0 / s - f_normal * v_s * dvs_dfn / (s * s * s);
  const Vec3 df_dfn = n - m.friction * dq_dfn * v_tangent;  // f's change per unit of f_n
  // D: f_n falls with the separation speed (slope -c along n); the friction turns with v_t.
  r.D_rel = -damping * df_dfn * n.transpose() -
            m.friction *
                ((f_normal / s) * P - (f_normal / (s * s * s)) * v_tangent * v_tangent.transpose());
  r.K_rel = -dfn_dd * df_dfn * n.transpose();
  return r;
}

// f_t = -k_t xi - gt v_t (k_t = kt sqrt(R d)) while |f_t| <= u f_n, else u f_n along it.
SmoothCollisionForce::Response SmoothCollisionForce::RespondWithSpring(const PairMaterial& m,
                                                                       const Normal& normal,
                                                                       const Vec3& v_tangent,
                                                                       const Vec3& xi, bool slopes,
                                                                       Response r) {
  const Vec3& n = normal.n;
  const double friction = normal.friction;
  const double k_t = m.kt * normal.sqrt_Rd;
  const Vec3 trial = -k_t * xi - m.gt * v_tangent;
  const double size = trial.norm();
  const bool slips = size > friction;
  r.energy += 0.5 * k_t * xi.squaredNorm();
  r.f = normal.force * n + (slips ? Vec3((friction / size) * trial) : trial);
  if (!slopes) return r;
  // In slip f_t = u f_n t, t = trial / |trial|: its change is u f_n / |trial| (I - t t^T) times
  // the trial's, plus u t per unit of f_n.
  const Vec3 t = slips ? Vec3(trial / size) : Vec3::Zero();
  const Mat3 turn =
      slips ? Mat3((friction / size) * (Mat3::Identity() - t * t.transpose())) : Mat3::Identity();
  const Vec3 df_dfn = n + m.friction * t;
  const Mat3 P = Mat3::Identity() - n * n.transpose();  // onto the tangent plane
  r.D_rel = -normal.damping * df_dfn * n.transpose() - m.gt * turn * P;
  // Body 2's point moved by dx stretches xi by P dx and, along +n, shallows the contact, which
  // softens k_t = kt sqrt(R d) (dk_t/dd = k_t / 2d).
  r.K_rel = -normal.dfn_dd * df_dfn * n.transpose() - k_t * turn * P +
            turn * (0.5 * k_t / normal.d) * xi * n.transpose();
  return r;
}

std::shared_ptr<const engine::DiscreteData> SmoothCollisionForce::UpdateDiscreteData(
    const engine::ForceContext& context) const {
  const engine::State& state = context.state;
  auto history = std::make_shared<History>();
  const History* previous = FindHistory(state);
  GatherBodyPoses(state, history->X_GB);
  const std::vector<Transform>& X_GB = history->X_GB;
  detector_->FindContacts(X_GB, [&](const CollisionContact& c) {
    history->found.push_back(c);
    if (!(c.material.kt > 0.0)) return;
    // A new contact's spring starts unstretched.
    Vec3 xi = TangentialDisplacement(previous, X_GB, c).value_or(Vec3::Zero());
    const Response r = Respond(c, RelativeVelocity(state, c), &xi, /*slopes=*/false);
    if (!(r.normal > 0.0)) return;
    // A slipping contact's spring stays stretched to the Coulomb limit.
    const double spring = c.material.kt * std::sqrt(c.radius * c.depth) * xi.norm();
    const double limit = c.material.friction * r.normal;
    if (spring > limit) xi *= limit / spring;
    history->contacts.push_back(
        {c.body1, c.body2, X_GB[c.body1].Inverse() * c.p_G, X_GB[c.body2].Inverse() * c.p_G, xi});
  });
  return history;
}

bool SmoothCollisionForce::CalcLoadJacobians(const engine::ForceContext& context,
                                             Eigen::Ref<MatX> K, Eigen::Ref<MatX> D) const {
  const engine::State& state = context.state;
  const std::optional<engine::ForceSupport> support = Support();
  std::vector<int> column(state.bodies.size(), -1);  // each body's first column in K and D
  for (size_t i = 0; i < support->bodies.size(); ++i)
    column[support->bodies[i]] = 6 * static_cast<int>(i);
  std::vector<Transform> X_GB;
  GatherBodyPoses(state, X_GB);
  const History* history = FindHistory(state);
  ForEachContact(history, X_GB, [&](const CollisionContact& c) {
    const std::optional<Vec3> xi = TangentialDisplacement(history, X_GB, c);
    const Response r = Respond(c, RelativeVelocity(state, c), xi ? &*xi : nullptr, /*slopes=*/true);
    // Body b's point moves as G_b = [-[p - Bo]x  I] times its twist; body 2's load is G_2^T f,
    // body 1's -G_1^T f.
    const int body[2] = {c.body1, c.body2};
    Eigen::Matrix<double, 3, 6> G[2];
    for (int k = 0; k < 2; ++k) G[k] << -Skew(c.p_G - state.bodies[body[k]].p_GB), Mat3::Identity();
    for (int a = 0; a < 2; ++a) {
      if (column[body[a]] < 0) continue;
      for (int b = 0; b < 2; ++b) {
        if (column[body[b]] < 0) continue;
        const double sign = a == b ? 1.0 : -1.0;
        D.block<6, 6>(column[body[a]], column[body[b]]) += sign * G[a].transpose() * r.D_rel * G[b];
        K.block<6, 6>(column[body[a]], column[body[b]]) += sign * G[a].transpose() * r.K_rel * G[b];
      }
    }
  });
  return true;
}

}  // namespace sinew::contact

// SMC, the seed's smooth contact method (contact::SmoothCollisionForce over the collision
// detector's contacts), against closed forms: a sphere launched sliding on a plane reaches
// rolling at 5/7 of its speed when Coulomb's law says, and a box on an incline creeps below the
// friction angle at the speed the friction regularization gives and slides with
// g (sin a - u cos a) above it. With tangential springs (kt) the box sticks instead, a ball on
// a spring rocks about its rolling speed as the closed form says (keeping its energy), and a
// sliding ball slips at exactly Coulomb's limit before it rolls. A cylinder stands on the four
// points of its cap.
#include <gtest/gtest.h>
#include <sinew/contact/smooth_collision_force.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/dynamics.h>
#include <sinew/engine/energy.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/state.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <numbers>

#include "contact/contact_models.h"

namespace sinew::contact {
namespace {

constexpr double kG = 9.80665;

// The Hertz effective modulus of two shapes of one material.
double SameMaterialModulus(const CollisionMaterial& m) {
  return m.young_modulus / (2.0 * (1.0 - m.poisson_ratio * m.poisson_ratio));
}

// The depth at which a Hertz contact of effective radius R carries `load`.
double HertzDepth(double load, double modulus, double radius) {
  return std::pow(load / (4.0 / 3.0 * modulus * std::sqrt(radius)), 2.0 / 3.0);
}

// The model's ContactSphere (m = 1 kg, r = 0.1 m, I = 2/5 m r^2) and ContactHalfSpace floor
// as collision shapes, no contact force in the file, SMC with `material` and slip speed `vs`:
// resting at its Hertz depth d, sliding at `v0` along x without spin.
constexpr double kM = 1.0, kR = 0.1, kInertia = 0.4 * kM * kR * kR;
struct SlidingBall {
  engine::System system{Vec3(0, -kG, 0)};
  engine::State state;
  double d = 0.0;    // the Hertz depth under the weight
  double rho = 0.0;  // the contact point's distance from the centre, r - d / 2
  // The contact point's slip speed along x (the ball's point at the contact, d/2 below the
  // floor, less the floor's).
  double Slip(const engine::State& s) const {
    const engine::BodyState& b = s.bodies[1];
    return (b.v_GB + b.w_GB.cross(Vec3(0, -(b.p_GB.y() + d / 2.0), 0))).x();
  }
};

// The ball's model: the sphere on a free body over the ContactHalfSpace floor.
model::ModelSpec BallSpec() {
  return io::ReadOsimString(testing::FreeBodyContactModel(kM, Vec3::Constant(kInertia),
                                                          Vec3(0, -kG, 0), kR, {Vec3::Zero()}, ""),
                            "ball.osim");
}

std::unique_ptr<SlidingBall> MakeSlidingBall(const CollisionMaterial& material, double vs,
                                             double v0) {
  auto ball = std::make_unique<SlidingBall>();
  opensim::OpenSimParser parser;
  parser.EnableCollision();
  parser.SetContactMethod(ContactMethod::kSmc);
  parser.SetContactMaterial(material);
  parser.SetFrictionSlipSpeed(vs);
  parser.ParseSpec(ball->system, BallSpec());
  ball->system.Finalize();
  ball->d = HertzDepth(kM * kG, SameMaterialModulus(material), kR);
  ball->rho = kR - ball->d / 2.0;
  ball->state = engine::MakeDefaultState(ball->system);
  engine::SetCoordinateValue(ball->system, ball->state, "ty", kR - ball->d);
  engine::SetCoordinateSpeed(ball->system, ball->state, "tx", v0);
  return ball;
}

TEST(SmoothContactTest, SlidingSphereRollsAtFiveSeventhsOfItsSpeed) {
  // The sliding ball with E = 1e9 Pa, nu = 0.3, u = 0.5, e = 0.5, slip speed v_s = 1e-4 m/s,
  // v0 = 1 m/s. The contact point is d/2 below the floor, at rho = r - d/2 from
  // the centre. With f = u m g s / sqrt(s^2 + v_s^2) the slip s = v - w rho obeys
  // s' = -k s / sqrt(s^2 + v_s^2), k = u g (1 + m rho^2 / I), so it falls from v0 to s1 at
  // t1 = (F(v0) - F(s1)) / k, F(s) = sqrt(s^2 + v_s^2) - v_s ln((v_s + sqrt(s^2 + v_s^2)) / s);
  // the angular momentum about the contact line is kept, so it rolls at v0 / (1 + I / (m rho^2)).
  // Coulomb's law (v_s -> 0, d -> 0): t* = 2 v0 / (7 u g), 5/7 v0.
  constexpr double kMu = 0.5, kVs = 1e-4, kV0 = 1.0, kS1 = 1e-3;
  CollisionMaterial material;
  material.young_modulus = 1e9;
  material.friction = kMu;
  material.restitution = 0.5;
  auto ball = MakeSlidingBall(material, kVs, kV0);
  const double rho = ball->rho, inertia = kInertia;
  engine::State& state = ball->state;
  auto integrator = engine::MakeIntegrator("rk45", ball->system, {.accuracy = 1e-10});
  auto slip = [&](const engine::State& s) { return ball->Slip(s); };
  double t1 = -1.0, previous = slip(state);
  constexpr double kDt = 1e-5;
  for (int n = 1; n <= 10000; ++n) {
    integrator->StepTo(state, kDt * n);
    const double s = slip(state);
    if (t1 < 0.0 && s <= kS1) t1 = kDt * (n - 1) + kDt * (previous - kS1) / (previous - s);
    previous = s;
  }
  const auto F = [&](double s) {
    const double h = std::sqrt(s * s + kVs * kVs);
    return h - kVs * std::log((kVs + h) / s);
  };
  const double t1_closed = (F(kV0) - F(kS1)) / (kMu * kG * (1.0 + kM * rho * rho / inertia));
  const double v_closed = kV0 / (1.0 + inertia / (kM * rho * rho));
  const double t_coulomb = 2.0 * kV0 / (7.0 * kMu * kG);
  const double v = state.bodies[1].v_GB.x();
  EXPECT_NEAR(t1, t1_closed, 1e-5 * t1_closed);
  EXPECT_NEAR(v, v_closed, 1e-8 * v_closed);
  // Coulomb's figures, which the regularization (s1 / v0 = 1e-3) and the dent shift by less.
  EXPECT_NEAR(t1, t_coulomb, 2e-3 * t_coulomb);
  EXPECT_NEAR(v, 5.0 / 7.0 * kV0, 2e-3 * kV0);
  EXPECT_LT(std::abs(slip(state)), 1e-6);
  std::cout << "SMC rolling: slip reaches " << kS1 << " at " << t1 << " s (closed form "
            << t1_closed << ", relative error " << t1 / t1_closed - 1 << "; Coulomb " << t_coulomb
            << ", " << t1 / t_coulomb - 1 << "), rolls at " << v << " m/s (closed form " << v_closed
            << ", " << v / v_closed - 1 << "; 5/7 v0, " << v / (5.0 / 7.0 * kV0) - 1 << ")\n";
}

// A free body of mass m (inertia `inertia`, gravity -y) whose contact is the SMC force element
// "smc" over `geometry` (ground shapes and the body's, named `shape`) of one `material`, that
// shape's loads reported; with `tangential_springs`, friction is the spring kept per contact.
std::unique_ptr<engine::System> SmcFreeBody(double m, const Vec3& inertia,
                                            const CollisionMaterial& material,
                                            std::vector<CollisionGeometry> geometry,
                                            const std::string& shape, bool tangential_springs) {
  const model::ModelSpec spec = io::ReadOsimString(
      testing::FreeBodyContactModel(m, inertia, Vec3(0, -kG, 0), 0.01, {}, ""), shape + ".osim");
  auto system = std::make_unique<engine::System>(spec.gravity);
  opensim::OpenSimParser parser;
  parser.ParseSpec(*system, spec);
  CollisionModel model;
  model.materials = {material};
  model.jointed = {{0, 1}};
  model.geometry = std::move(geometry);
  auto detector = std::make_shared<CollisionDetector>(model, std::nullopt);
  system->AddForceElement(std::make_shared<SmoothCollisionForce>(
      "smc", detector, std::vector<double>{0.0, m}, 1e-3,
      std::vector<ContactForce::RecordGroup>{{shape, 1}}, std::vector<ContactForce::PairGroup>{},
      tangential_springs));
  system->Finalize();
  return system;
}

// A 1 kg box (half extents 0.1, 0.05, 0.1 m) on a plane tilted by `angle` about z (downhill
// +x cos a - y sin a), material E = 1e8 Pa, nu = 0.3, u = 0.5, e = 0.5, slip speed 1e-3 m/s,
// through the force element itself (the box on the free body, the incline a ground
// half-space, or with `on_box` a ground box whose top face is that plane). Starts at rest on
// its four corners at their Hertz depth. With `kt` > 0 friction is the tangential spring
// (gt = 20 N s/m). Returns the downhill speed at 0.5 s and 1 s.
std::pair<double, double> BoxDownhillSpeeds(double angle, double mu, bool on_box = false,
                                            double kt = 0.0) {
  const Vec3 h(0.1, 0.05, 0.1);
  const double m = 1.0;
  CollisionMaterial material;
  material.young_modulus = 1e8;
  material.friction = mu;
  material.restitution = 0.5;
  material.kt = kt;
  material.gt = kt > 0.0 ? 20.0 : 0.0;
  const Vec3 downhill(std::cos(angle), -std::sin(angle), 0);
  const Vec3 normal(std::sin(angle), std::cos(angle), 0);
  std::vector<CollisionGeometry> geometry;
  Mat3 R_GS;
  R_GS << -normal, downhill, Vec3::UnitZ();  // S's x into the solid
  if (on_box) {  // 6 m downhill, 2 m across, 1 m thick: S's y along the normal
    Mat3 R_GF;
    R_GF << downhill, normal, Vec3::UnitZ();
    geometry.push_back({"incline", CollisionShapeKind::kBox, 0, Transform(R_GF, -0.5 * normal), 0.0,
                        Vec3(3.0, 0.5, 1.0)});
  } else {
    geometry.push_back(
        {"incline", CollisionShapeKind::kHalfSpace, 0, Transform(R_GS, Vec3::Zero())});
  }
  geometry.push_back({"box", CollisionShapeKind::kBox, 1, Transform(), 0.0, h});
  const Vec3 inertia = m / 3.0 *
                       Vec3(h.y() * h.y() + h.z() * h.z(), h.x() * h.x() + h.z() * h.z(),
                            h.x() * h.x() + h.y() * h.y());
  const std::unique_ptr<engine::System> owned =
      SmcFreeBody(m, inertia, material, std::move(geometry), "box", kt > 0.0);
  const engine::System& system = *owned;
  // On a box's face as on a plane: a box corner's radius.
  const double d =
      HertzDepth(m * kG * std::cos(angle) / 4.0, SameMaterialModulus(material), kFlatShapeRadius);
  engine::State state = engine::MakeDefaultState(system);
  const Vec3 p = (h.y() - d) * normal;
  engine::SetCoordinateValue(system, state, "rz", -angle);
  engine::SetCoordinateValue(system, state, "tx", p.x());
  engine::SetCoordinateValue(system, state, "ty", p.y());
  engine::IntegratorSettings settings;
  settings.accuracy = 1e-9;
  auto integrator = engine::MakeIntegrator("rk45", system, settings);
  integrator->StepTo(state, 0.5);
  const double v_half = state.bodies[1].v_GB.dot(downhill);
  integrator->StepTo(state, 1.0);
  return {v_half, state.bodies[1].v_GB.dot(downhill)};
}

TEST(SmoothContactTest, BoxCreepsBelowTheFrictionAngleAndSlidesAboveIt) {
  constexpr double kMu = 0.5, kVs = 1e-3;
  // Below (20 degrees, tan = 0.364 < 0.5): Coulomb's box sticks. The regularized friction
  // u f_n s / sqrt(s^2 + v_s^2) balances m g sin a, with f_n summing to m g cos a over the
  // corners, at the creep s = v_s tan(a) / sqrt(u^2 - tan(a)^2) (1.06 mm/s here): the creep is
  // bounded by the regularization, and vanishes with v_s.
  // The same on a ground box (Bullet's box-box detector: the face's four corners).
  for (const bool on_box : {false, true}) {
    SCOPED_TRACE(on_box ? "on a ground box" : "on a half-space");
    const double below = 20.0 * std::numbers::pi / 180.0;
    const auto [creep_half, creep] = BoxDownhillSpeeds(below, kMu, on_box);
    const double t = std::tan(below);
    const double creep_closed = kVs * t / std::sqrt(kMu * kMu - t * t);
    EXPECT_NEAR(creep, creep_closed, 1e-6 * creep_closed);
    EXPECT_NEAR(creep_half, creep_closed, 1e-3 * creep_closed);
    // Above (35 degrees, tan = 0.700): it slides with a = g (sin a - u cos a), less the
    // regularization's (v_s / v)^2 / 2 < 1e-5 relative at the speeds reached (> 0.3 m/s).
    const double above = 35.0 * std::numbers::pi / 180.0;
    const auto [v_half, v_one] = BoxDownhillSpeeds(above, kMu, on_box);
    const double acceleration = (v_one - v_half) / 0.5;
    const double closed = kG * (std::sin(above) - kMu * std::cos(above));
    EXPECT_NEAR(acceleration, closed, 1e-5 * closed);
    std::cout << "SMC incline: creep at 20 deg " << creep << " m/s (closed form " << creep_closed
              << ", relative error " << creep / creep_closed - 1 << "), acceleration at 35 deg "
              << acceleration << " m/s^2 (closed form " << closed << ", relative error "
              << acceleration / closed - 1 << ")" << (on_box ? " on a ground box" : "") << "\n";
  }
}

// Below the friction angle the same box with a tangential stiffness (kt = 1e8 Pa, damped by
// gt = 20 N s/m) does not creep: each corner's spring holds its share of m g sin a (the spring
// forces sum to m g sin a = 3.35 N, below u m g cos a = 4.61 N), and the box comes to rest,
// where the regularized friction lets it creep at 1.06 mm/s. Above the angle it slides as
// Coulomb's box does, the springs stretched to the cap.
TEST(SmoothContactTest, TangentialSpringHoldsTheBoxBelowTheFrictionAngle) {
  constexpr double kMu = 0.5;
  for (const bool on_box : {false, true}) {
    SCOPED_TRACE(on_box ? "on a ground box" : "on a half-space");
    const auto [v_half, v_one] =
        BoxDownhillSpeeds(20.0 * std::numbers::pi / 180.0, kMu, on_box, /*kt=*/1e8);
    EXPECT_LT(std::abs(v_half), 1e-8);
    EXPECT_LT(std::abs(v_one), 1e-9);
    const double above = 35.0 * std::numbers::pi / 180.0;
    const auto [s_half, s_one] = BoxDownhillSpeeds(above, kMu, on_box, /*kt=*/1e8);
    const double acceleration = (s_one - s_half) / 0.5;
    const double closed = kG * (std::sin(above) - kMu * std::cos(above));
    EXPECT_NEAR(acceleration, closed, 1e-6 * closed);
    std::cout << "SMC tangential spring on the incline: speed " << v_half << " m/s at 0.5 s, "
              << v_one << " m/s at 1 s at 20 deg; acceleration at 35 deg " << acceleration
              << " m/s^2 (closed form " << closed << ", relative error "
              << acceleration / closed - 1 << ")" << (on_box ? " on a ground box" : "") << "\n";
  }
}

// NSC uses a material's friction and restitution only: the SMC parameters a material sets
// (here kt and gt) are a warning naming them under NSC, and none under SMC.
TEST(SmoothContactTest, SmcMaterialParametersAreAWarningOnlyUnderNsc) {
  CollisionMaterial material;
  material.kt = 1e6;
  material.gt = 5.0;
  for (const ContactMethod method : {ContactMethod::kNsc, ContactMethod::kSmc}) {
    opensim::OpenSimParser parser;
    parser.EnableCollision();
    parser.SetContactMethod(method);
    parser.SetContactMaterial(material);
    engine::System system(Vec3(0, -kG, 0));
    parser.ParseSpec(system, BallSpec());
    int warnings = 0;
    for (const Diagnostic& w : parser.GetReport().warnings()) {
      if (w.message.find("kt, gt: SMC's contact parameters, which NSC ignores") !=
          std::string::npos) {
        ++warnings;
      }
    }
    EXPECT_EQ(warnings, method == ContactMethod::kNsc ? 1 : 0);
  }
}

// With a tangential stiffness kt the friction is a spring on the contact points' displacement
// xi (kept from step to step), capped at u f_n. The sliding ball at v0 = 1 cm/s without spin,
// E = 1e9 Pa, kt = 1e6 Pa, u = 10 (the spring stays far below the cap), gt = 0. xi' is the
// slip s, and the spring's -k xi (k = kt sqrt(r d)) at the contact point, rho below the centre,
// slows the centre by k xi / m and spins the ball: s' = -k xi (1 / m + rho^2 / I) = -k xi / m_e.
// So xi = (v0 / W) sin(W t) with W = sqrt(k / m_e), and the centre's speed
// v = v0 - (k / m) int xi dt = v0 (1 - (m_e / m) (1 - cos W t)) swings between v0 and
// v0 (1 - 2 m_e / m), about v0 (1 - m_e / m) (5/7 v0 and 3/7 v0 as rho -> r). Undamped, the
// energy with the spring's 1/2 k xi^2 is kept.
TEST(SmoothContactTest, TangentialSpringRocksARollingSphereAboutFiveSevenths) {
  constexpr double kV0 = 0.01;
  CollisionMaterial material;
  material.young_modulus = 1e9;
  material.friction = 10.0;
  material.restitution = 0.5;
  material.kt = 1e6;
  auto ball = MakeSlidingBall(material, 1e-4, kV0);
  ASSERT_TRUE(ball->system.HasDiscreteData());
  const double k = material.kt * std::sqrt(kR * ball->d);
  const double m_e = 1.0 / (1.0 / kM + ball->rho * ball->rho / kInertia);
  const double w = std::sqrt(k / m_e);
  auto integrator = engine::MakeIntegrator("rk45", ball->system, {.accuracy = 1e-10});
  engine::State& state = ball->state;
  const double energy0 = engine::CalcMechanicalEnergy(ball->system, state);
  double worst = 0.0, worst_energy = 0.0;
  const double period = 2.0 * std::numbers::pi / w;
  for (int n = 1; n <= 40; ++n) {  // two periods
    const double t = n * period / 20.0;
    integrator->StepTo(state, t);
    const double v = state.bodies[1].v_GB.x();
    const double closed = kV0 * (1.0 - m_e / kM * (1.0 - std::cos(w * t)));
    worst = std::max(worst, std::abs(v - closed));
    worst_energy = std::max(worst_energy,
                            std::abs(engine::CalcMechanicalEnergy(ball->system, state) - energy0));
  }
  const double kinetic0 = 0.5 * kM * kV0 * kV0;
  std::cout << "SMC tangential spring: period " << period << " s, rolling speed "
            << kV0 * (1.0 - m_e / kM) << " m/s; worst speed error " << worst
            << " m/s, energy change " << worst_energy << " J of " << kinetic0 << " J kinetic\n";
  EXPECT_LT(worst, 1e-6 * kV0);
  EXPECT_LT(worst_energy, 1e-6 * kinetic0);
  EXPECT_EQ(state.discrete.size(), 1u);
}

// The same ball at v0 = 1 m/s with u = 0.5, kt = 1e6 Pa and gt = 2 sqrt(k m_e) (the spring's
// oscillation critically damped). While it slips the friction is exactly u f_n (the spring
// stays stretched to the cap; no regularization), so the slip falls linearly,
// s = v0 - u g (1 + m rho^2 / I) t, to 0 at Coulomb's time for the dented ball; then the
// spring holds the contact point and the ball rolls at v0 / (1 + I / (m rho^2)) + (2/7) s
// (its angular momentum about the contact line is kept). The spring's displacement is kept
// from the bodies' points at the contact, which a rolling ball carries off the contact within
// a step (by rho (w h - sin w h), a cycloid): a rolling contact creeps at about
// rho w^3 h^2 / 6, 2.4e-7 m/s at steps of h = 0.2 ms (1.6e-5 m/s at rk45's own 1.6 ms).
TEST(SmoothContactTest, TangentialSpringSlipsAtTheCoulombLimitThenRolls) {
  constexpr double kV0 = 1.0, kMu = 0.5;
  CollisionMaterial material;
  material.young_modulus = 1e9;
  material.friction = kMu;
  material.restitution = 0.5;
  material.kt = 1e6;
  auto ball = MakeSlidingBall(material, 1e-4, kV0);
  const double k = material.kt * std::sqrt(kR * ball->d);
  const double rho = ball->rho;
  const double m_e = 1.0 / (1.0 / kM + rho * rho / kInertia);
  material.gt = 2.0 * std::sqrt(k * m_e);
  ball = MakeSlidingBall(material, 1e-4, kV0);
  constexpr double kStep = 2e-4;
  auto integrator =
      engine::MakeIntegrator("rk45", ball->system, {.accuracy = 1e-10, .step = kStep});
  const double deceleration = kMu * kG * (1.0 + kM * rho * rho / kInertia);
  double worst = 0.0;
  const double t_roll = kV0 / deceleration;
  for (int n = 1; n <= 20; ++n) {  // the slipping phase, to 95% of it
    const double t = 0.95 * t_roll * n / 20.0;
    integrator->StepTo(ball->state, t);
    worst = std::max(worst, std::abs(ball->Slip(ball->state) - (kV0 - deceleration * t)));
  }
  integrator->StepTo(ball->state, 1.0);
  const double v = ball->state.bodies[1].v_GB.x();
  const double v_closed = kV0 / (1.0 + kInertia / (kM * rho * rho));
  const double w = v_closed / rho;
  const double creep = rho * w * w * w * kStep * kStep / 6.0;
  std::cout << "SMC tangential spring, slipping: slip off the linear law by at most " << worst
            << " m/s until " << 0.95 * t_roll << " s; rolls at " << v << " m/s (closed form "
            << v_closed << ", relative error " << v / v_closed - 1 << "), creeping at "
            << ball->Slip(ball->state) << " m/s (bound " << creep << ")\n";
  EXPECT_LT(worst, 1e-6 * kV0);
  EXPECT_LT(std::abs(ball->Slip(ball->state)), 2.0 * creep);
  EXPECT_NEAR(v, v_closed, 2.0 / 7.0 * 2.0 * creep);
}

// The spring update searches the contacts at the step's end and keeps them; the next step starts
// at exactly those poses and uses them instead of searching again. They must be the contacts a
// search finds there: the loads with the kept contacts equal those of a search at poses one
// rounding step away (the ball moved by one unit in the last place, which no kept contact
// matches bit for bit, so that evaluation searches).
TEST(SmoothContactTest, ContactsKeptByTheSpringUpdateAreTheOnesASearchFinds) {
  CollisionMaterial material;
  material.young_modulus = 1e9;
  material.friction = 0.5;
  material.restitution = 0.5;
  material.kt = 1e6;
  material.gt = 20.0;
  auto ball = MakeSlidingBall(material, 1e-4, 0.1);
  auto integrator = engine::MakeIntegrator("euler", ball->system, {.step = 1e-4});
  integrator->StepTo(ball->state, 2e-3);
  ASSERT_EQ(ball->state.discrete.size(), 1u);
  const engine::System& system = ball->system;
  engine::Loads kept(system.num_bodies(), system.num_coordinates());
  engine::Loads searched = kept;
  engine::CalcLoads(ball->system, ball->state, nullptr, kept);
  engine::State moved = ball->state;
  double& x = moved.bodies[1].p_GB.x();
  x = std::nextafter(x, 1.0);
  engine::CalcLoads(ball->system, moved, nullptr, searched);
  const double weight = kM * kG;
  const SpatialVec& a = kept.body[1];
  const SpatialVec& b = searched.body[1];
  std::cout << "SMC kept contacts: ball load " << a.transpose() << ", by a search one ulp away "
            << b.transpose() << "\n";
  // The contact carries the weight (the loads include gravity's -m g) and a spring friction
  // (the ball was launched sliding).
  EXPECT_GT(a.tail<3>().y() + weight, 0.5 * weight);
  EXPECT_GT(std::abs(a.tail<3>().x()), 1e-3 * weight);
  EXPECT_LT((a - b).norm(), 1e-12 * weight);
}

// A cylinder (m = 1 kg, r = 0.1 m, 0.4 m long) standing on its cap on the floor at the Hertz
// depth of a quarter of its weight: its cap's four rim points a quarter turn apart carry it,
// so the loads on it (gravity's included) vanish, force and torque, to rounding. Tilted by
// 0.01 rad about x, the rim's lower side carries more and the torque rights it. (On the cap's
// one deepest rim point it was pushed over: a torque of about m g r at rest.)
TEST(SmoothContactTest, CylinderStandsOnTheFourPointsOfItsCap) {
  constexpr double m = 1.0, r = 0.1, half_length = 0.2;
  CollisionMaterial material;
  material.young_modulus = 1e8;
  Mat3 R_GF;  // the floor: its x into the solid y < 0
  R_GF << -Vec3::UnitY(), Vec3::UnitX(), Vec3::UnitZ();
  CollisionGeometry cylinder;  // its axis (z) turned onto y: standing
  cylinder.name = "cylinder";
  cylinder.kind = CollisionShapeKind::kCylinder;
  cylinder.body = 1;
  cylinder.radius = r;
  cylinder.half_length = half_length;
  cylinder.X_BS = Transform(
      Eigen::AngleAxisd(-std::numbers::pi / 2, Vec3::UnitX()).toRotationMatrix(), Vec3::Zero());
  const std::unique_ptr<engine::System> owned = SmcFreeBody(
      m, Vec3::Ones(), material,
      {{"floor", CollisionShapeKind::kHalfSpace, 0, Transform(R_GF, Vec3::Zero())}, cylinder},
      "cylinder", false);
  const engine::System& system = *owned;
  const double d = HertzDepth(m * kG / 4.0, SameMaterialModulus(material), r);
  engine::State state = engine::MakeDefaultState(system);
  engine::SetCoordinateValue(system, state, "ty", half_length - d);
  engine::Loads loads(system.num_bodies(), system.num_coordinates());
  engine::CalcLoads(system, state, nullptr, loads);
  const double weight = m * kG;
  // Each depth is a difference of positions near 0.2 m (about 3e-17 m of rounding) against a
  // depth of a few micrometres: 1e-10 relative allows for it.
  EXPECT_NEAR(loads.body[1].tail<3>().norm(), 0.0, 1e-10 * weight);
  EXPECT_NEAR(loads.body[1].head<3>().norm(), 0.0, 1e-10 * weight * r);
  std::cout << "SMC standing cylinder at the Hertz depth " << d << " m of m g / 4: load "
            << loads.body[1].transpose() << "\n";
  engine::SetCoordinateValue(system, state, "rx", 0.01);  // its foot at +z sinks deeper
  engine::CalcLoads(system, state, nullptr, loads);
  EXPECT_LT(loads.body[1].head<3>().x(), -0.01 * weight * r);  // turning it back
}

}  // namespace
}  // namespace sinew::contact

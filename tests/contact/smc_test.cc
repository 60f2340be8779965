// SMC, the seed's smooth contact method (contact::SmoothCollisionForce over the collision
// detector's contacts), against closed forms: a sphere launched sliding on a plane reaches
// rolling at 5/7 of its speed when Coulomb's law says, and a box on an incline creeps below the
// friction angle at the speed the friction regularization gives and slides with
// g (sin a - u cos a) above it.
#include <gtest/gtest.h>
#include <sinew/contact/smooth_collision_force.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/state.h>

#include <cmath>
#include <iostream>
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

TEST(SmoothContactTest, SlidingSphereRollsAtFiveSeventhsOfItsSpeed) {
  // The model's ContactSphere (m = 1 kg, r = 0.1 m, I = 2/5 m r^2) and ContactHalfSpace floor
  // as collision shapes, no contact force in the file; SMC with E = 1e9 Pa, nu = 0.3, u = 0.5,
  // e = 0.5, slip speed v_s = 1e-4 m/s. It starts resting at its Hertz depth d, sliding at
  // v0 = 1 m/s without spin. The contact point is d/2 below the floor, at rho = r - d/2 from
  // the centre. With f = u m g s / sqrt(s^2 + v_s^2) the slip s = v - w rho obeys
  // s' = -k s / sqrt(s^2 + v_s^2), k = u g (1 + m rho^2 / I), so it falls from v0 to s1 at
  // t1 = (F(v0) - F(s1)) / k, F(s) = sqrt(s^2 + v_s^2) - v_s ln((v_s + sqrt(s^2 + v_s^2)) / s);
  // the angular momentum about the contact line is kept, so it rolls at v0 / (1 + I / (m rho^2)).
  // Coulomb's law (v_s -> 0, d -> 0): t* = 2 v0 / (7 u g), 5/7 v0.
  constexpr double kM = 1.0, kR = 0.1, kMu = 0.5, kVs = 1e-4, kV0 = 1.0, kS1 = 1e-3;
  const double inertia = 0.4 * kM * kR * kR;
  CollisionMaterial material;
  material.young_modulus = 1e9;
  material.friction = kMu;
  material.restitution = 0.5;
  opensim::OpenSimParser parser;
  parser.EnableCollision();
  parser.SetContactMethod(ContactMethod::kSmc);
  parser.SetContactMaterial(material);
  parser.SetFrictionSlipSpeed(kVs);
  const model::ModelSpec spec =
      io::ReadOsimString(testing::FreeBodyContactModel(kM, Vec3::Constant(inertia), Vec3(0, -kG, 0),
                                                       kR, {Vec3::Zero()}, ""),
                         "rolling_ball.osim");
  engine::System system(spec.gravity);
  parser.ParseSpec(system, spec);
  system.Finalize();
  const double d = HertzDepth(kM * kG, SameMaterialModulus(material), kR);
  const double rho = kR - d / 2.0;
  engine::State state = engine::MakeDefaultState(system);
  engine::SetCoordinateValue(system, state, "ty", kR - d);
  engine::SetCoordinateSpeed(system, state, "tx", kV0);
  engine::IntegratorSettings settings;
  settings.accuracy = 1e-10;
  auto integrator = engine::MakeIntegrator("rk45", system, settings);

  auto slip = [&](const engine::State& s) {
    const engine::BodyState& b = s.bodies[1];
    return (b.v_GB + b.w_GB.cross(Vec3(0, -(b.p_GB.y() + d / 2.0), 0))).x();
  };
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

// A 1 kg box (half extents 0.1, 0.05, 0.1 m) on a plane tilted by `angle` about z (downhill
// +x cos a - y sin a), material E = 1e8 Pa, nu = 0.3, u = 0.5, e = 0.5, slip speed 1e-3 m/s,
// through the force element itself (the box on the free body, the incline a ground
// half-space, or with `on_box` a ground box whose top face is that plane). Starts at rest on
// its four corners at their Hertz depth. Returns the downhill speed at 0.5 s and 1 s.
std::pair<double, double> BoxDownhillSpeeds(double angle, double mu, bool on_box = false) {
  const Vec3 h(0.1, 0.05, 0.1);
  const double m = 1.0;
  const model::ModelSpec spec =
      io::ReadOsimString(testing::FreeBodyContactModel(
                             m,
                             m / 3.0 *
                                 Vec3(h.y() * h.y() + h.z() * h.z(), h.x() * h.x() + h.z() * h.z(),
                                      h.x() * h.x() + h.y() * h.y()),
                             Vec3(0, -kG, 0), 0.01, {}, ""),
                         "incline_box.osim");
  engine::System system(spec.gravity);
  opensim::OpenSimParser parser;
  parser.ParseSpec(system, spec);
  CollisionMaterial material;
  material.young_modulus = 1e8;
  material.friction = mu;
  material.restitution = 0.5;
  CollisionModel model;
  model.materials = {material};
  model.jointed = {{0, 1}};
  const Vec3 downhill(std::cos(angle), -std::sin(angle), 0);
  const Vec3 normal(std::sin(angle), std::cos(angle), 0);
  Mat3 R_GS;
  R_GS << -normal, downhill, Vec3::UnitZ();  // S's x into the solid
  if (on_box) {  // 6 m downhill, 2 m across, 1 m thick: S's y along the normal
    Mat3 R_GF;
    R_GF << downhill, normal, Vec3::UnitZ();
    model.geometry.push_back({"incline", CollisionShapeKind::kBox, 0,
                              Transform(R_GF, -0.5 * normal), 0.0, Vec3(3.0, 0.5, 1.0)});
  } else {
    model.geometry.push_back(
        {"incline", CollisionShapeKind::kHalfSpace, 0, Transform(R_GS, Vec3::Zero())});
  }
  model.geometry.push_back({"box", CollisionShapeKind::kBox, 1, Transform(), 0.0, h});
  auto detector = std::make_shared<CollisionDetector>(model, std::nullopt);
  system.AddForceElement(std::make_shared<SmoothCollisionForce>(
      "smc", detector, std::vector<double>{0.0, m}, 1e-3,
      std::vector<ContactForce::RecordGroup>{{"box", 1}}, std::vector<ContactForce::PairGroup>{}));
  system.Finalize();
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

}  // namespace
}  // namespace sinew::contact

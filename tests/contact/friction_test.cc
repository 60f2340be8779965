// Friction of OpenSim's HuntCrossleyForce against Coulomb's closed forms: a sphere launched
// sliding on a floor reaches rolling at 5/7 of its speed when the closed form says, and a block
// on three spheres creeps on an incline below the friction angle (at the speed the transition
// velocity's regularization gives) and slides with g (sin a - u cos a) above it.
#include <gtest/gtest.h>
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

TEST(HuntCrossleyFrictionTest, SlidingSphereRollsAtFiveSeventhsOfItsSpeed) {
  // A solid ball: m = 1 kg, r = 0.1 m, I = 2/5 m r^2; stiffness 1e9 Pa, dissipation 1 s/m,
  // u_s = u_d = u = 0.4, transition velocity v_t = 1e-3 m/s. It starts resting at its Hertz
  // depth d (4/3 k sqrt(r k) d^(3/2) = m g, k = (1e9)^(2/3) / 2), sliding at v0 = 1 m/s
  // without spin. The contact point is d/2 below the floor, at rho = r - d/2 from the centre.
  // While the slip s = v - w rho exceeds v_t the friction is u m g: v' = -u g,
  // w' = u m g rho / I, so s falls to v_t at t1 = (v0 - v_t) / (u g (1 + m rho^2 / I)). Then
  // the friction fades with the slip; the angular momentum about the contact line,
  // m v rho + I w, is kept throughout, so the ball rolls at v = v0 / (1 + I / (m rho^2)).
  // Coulomb's law (v_t -> 0, d -> 0) gives t* = 2 v0 / (7 u g) and 5/7 v0.
  constexpr double kM = 1.0, kR = 0.1, kMu = 0.4, kVt = 1e-3, kV0 = 1.0;
  const double inertia = 0.4 * kM * kR * kR;
  auto system = testing::ParseContactModel(
      testing::FreeBodyContactModel(kM, Vec3::Constant(inertia), Vec3(0, -kG, 0), kR,
                                    {Vec3::Zero()},
                                    testing::HuntCrossleyText(1, 1e9, 1.0, kMu, kVt)),
      "rolling_ball.osim");
  const double k = 0.5 * std::pow(1e9, 2.0 / 3.0);
  const double d = std::pow(kM * kG / (4.0 / 3.0 * k * std::sqrt(kR * k)), 2.0 / 3.0);
  const double rho = kR - d / 2.0;
  engine::State state = engine::MakeDefaultState(*system);
  engine::SetCoordinateValue(*system, state, "ty", kR - d);
  engine::SetCoordinateSpeed(*system, state, "tx", kV0);
  engine::IntegratorSettings settings;
  settings.accuracy = 1e-10;
  auto integrator = engine::MakeIntegrator("rk45", *system, settings);

  auto slip = [&](const engine::State& s) {
    const engine::BodyState& b = s.bodies[1];
    return (b.v_GB + b.w_GB.cross(Vec3(0, -(b.p_GB.y() + d / 2.0), 0))).x();
  };
  double t1 = -1.0, previous = slip(state);
  constexpr double kDt = 1e-5;
  for (int n = 1; n <= 20000; ++n) {
    integrator->StepTo(state, kDt * n);
    const double s = slip(state);
    if (t1 < 0.0 && s <= kVt) t1 = kDt * (n - 1) + kDt * (previous - kVt) / (previous - s);
    previous = s;
  }
  const double t1_closed = (kV0 - kVt) / (kMu * kG * (1.0 + kM * rho * rho / inertia));
  const double v_closed = kV0 / (1.0 + inertia / (kM * rho * rho));
  const double t_coulomb = 2.0 * kV0 / (7.0 * kMu * kG);
  const double v = state.bodies[1].v_GB.x();
  // Measured 1.3e-6 (the crossing is interpolated between samples 1e-5 s apart) and 2e-13.
  EXPECT_NEAR(t1, t1_closed, 1e-5 * t1_closed);
  EXPECT_NEAR(v, v_closed, 1e-9 * v_closed);
  // Coulomb's figures, which the regularization (v_t / v0 = 1e-3) and the dent shift by less.
  EXPECT_NEAR(t1, t_coulomb, 2e-3 * t_coulomb);
  EXPECT_NEAR(v, 5.0 / 7.0 * kV0, 2e-3 * kV0);
  EXPECT_LT(std::abs(slip(state)), 1e-6);
  std::cout << "rolling: relative errors " << t1 / t1_closed - 1 << " (time), " << v / v_closed - 1
            << " (speed)\n";
  std::cout << "rolling: slip reaches v_t at " << t1 << " s (closed form " << t1_closed
            << ", Coulomb " << t_coulomb << "), rolls at " << v << " m/s (closed form " << v_closed
            << ", 5/7 v0 " << 5.0 / 7.0 * kV0 << "), slip at 0.2 s " << slip(state) << " m/s\n";
}

// A 1 kg block on three spheres (r = 1 cm, an equilateral triangle of 0.1 m radius, 6 cm below
// its centre), stiffness 1e8 Pa, dissipation 20 s/m (its bounce on the floor dies out within
// 0.1 s), u = 0.5, v_t = 1e-3 m/s, on a floor tilted
// by `angle` (gravity turned instead: downhill is +x). Returns the downhill speed at 0.5 s and
// 1 s, after it has settled.
std::pair<double, double> DownhillSpeeds(double angle) {
  const double r = 0.01, a = 0.1;
  const std::vector<Vec3> feet = {Vec3(a, -0.05, 0), Vec3(-a / 2, -0.05, a * std::sqrt(3.0) / 2),
                                  Vec3(-a / 2, -0.05, -a * std::sqrt(3.0) / 2)};
  auto system = testing::ParseContactModel(
      testing::FreeBodyContactModel(1.0, Vec3(0.01, 0.01, 0.01),
                                    kG * Vec3(std::sin(angle), -std::cos(angle), 0), r, feet,
                                    testing::HuntCrossleyText(3, 1e8, 20.0, 0.5, 1e-3)),
      "incline_block.osim");
  engine::State state = engine::MakeDefaultState(*system);
  engine::SetCoordinateValue(*system, state, "ty", 0.05 + r);
  engine::IntegratorSettings settings;
  settings.accuracy = 1e-9;
  auto integrator = engine::MakeIntegrator("rk45", *system, settings);
  integrator->StepTo(state, 0.5);
  const double v_half = state.bodies[1].v_GB.x();
  integrator->StepTo(state, 1.0);
  return {v_half, state.bodies[1].v_GB.x()};
}

TEST(HuntCrossleyFrictionTest, BlockCreepsBelowTheFrictionAngleAndSlidesAboveIt) {
  constexpr double kMu = 0.5, kVt = 1e-3;
  // Below (20 degrees, tan = 0.364 < 0.5): Coulomb's block sticks. The regularized law gives
  // u f s / v_t below the transition velocity, so the block creeps at the steady slip where
  // that balances m g sin a: s = v_t tan(a) / u (0.73 mm/s here).
  const double below = 20.0 * std::numbers::pi / 180.0;
  const auto [creep_half, creep] = DownhillSpeeds(below);
  const double creep_closed = kVt * std::tan(below) / kMu;
  EXPECT_NEAR(creep, creep_closed, 1e-7 * creep_closed);       // measured 6e-9
  EXPECT_NEAR(creep_half, creep_closed, 1e-3 * creep_closed);  // steady from 0.5 s on
  // Above (35 degrees, tan = 0.700): it slides with a = g (sin a - u cos a).
  const double above = 35.0 * std::numbers::pi / 180.0;
  const auto [v_half, v_one] = DownhillSpeeds(above);
  const double acceleration = (v_one - v_half) / 0.5;
  const double closed = kG * (std::sin(above) - kMu * std::cos(above));
  EXPECT_NEAR(acceleration, closed, 1e-8 * closed);  // measured 2.6e-10
  std::cout << "incline: creep at 20 deg " << creep << " m/s (closed form " << creep_closed
            << ", relative error " << creep / creep_closed - 1 << "), acceleration at 35 deg "
            << acceleration << " m/s^2 (closed form " << closed << ", relative error "
            << acceleration / closed - 1 << ")\n";
}

}  // namespace
}  // namespace sinew::contact

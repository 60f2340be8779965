// Whole models read from an .osim file (tests/data/sinew/sliders.osim) and simulated, against
// closed forms: a CoordinateActuator driven beyond its max_control (unclamped, as OpenSim), and
// a prescribed coordinate with a free slider riding on it.
#include <gtest/gtest.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/integrator.h>
#include <sinew/forces/actuator.h>
#include <sinew/opensim/parser.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

namespace sinew {
namespace {

const std::string kSliders = std::string(SINEW_TEST_DATA_DIR) + "/sinew/sliders.osim";

constexpr double kGravity = 9.80665;

// cart_x(t) = 0.2 sin(4 t + 0.3) + 0.05 and its derivatives, as written in the file.
double Cart(double t) { return 0.2 * std::sin(4 * t + 0.3) + 0.05; }
double CartSpeed(double t) { return 0.8 * std::cos(4 * t + 0.3); }

// rk45 settings of these tests and the error bounds that follow from them. The three motions
// obey q'' = g(t) (no dependence on the state), so an error left in a speed at one step grows
// into a position error of at most (1 s) x itself by t = 1 s: after N steps the coordinates
// are within 2 N accuracy max(1, |q|) of the exact solution, and their speeds within
// N accuracy max(1, |u|).
engine::IntegratorSettings Settings() {
  engine::IntegratorSettings settings;
  settings.accuracy = 1e-10;
  return settings;
}

TEST(ClosedFormTest, CoordinateActuatorBeyondMaxControlIsNotClamped) {
  opensim::OpenSimParser parser;
  const auto system = parser.Parse(kSliders);
  const opensim::ForceInfo* lift = parser.GetReport().GetForce("lift_force");
  ASSERT_NE(lift, nullptr);
  ASSERT_NE(lift->actuator, nullptr);
  EXPECT_EQ(lift->excitation_source, "PrescribedController lift_controller");
  // The range is read, but (as OpenSim's CoordinateActuator::computeActuation, control x
  // optimal_force, with no bounds applied) the excitation 1.5 acts in full.
  EXPECT_EQ(lift->actuator->min_control(), -0.5);
  EXPECT_EQ(lift->actuator->max_control(), 0.5);
  EXPECT_EQ(parser.GetController()->Calc(lift->input, 0.7) * lift->actuator->optimal_force(),
            1.5 * 40.0);
  // height'' = F / m - g with F = 1.5 x 40 N, m = 2 kg: height = 0.3 + (30 - g) t^2 / 2.
  // (With the excitation clamped to 0.5 it would be 0.3 + (10 - g) t^2 / 2.)
  const double acceleration = 1.5 * 40.0 / 2.0 - kGravity;
  const engine::IntegratorSettings settings = Settings();
  auto integrator = engine::MakeIntegrator("rk45", *system, settings);
  integrator->SetController(parser.GetController());
  engine::State state = engine::MakeDefaultState(*system);
  double worst = 0.0, bound = 0.0;
  for (double t : {0.25, 0.5, 0.75, 1.0}) {
    integrator->StepTo(state, t);
    const double height = engine::GetCoordinateValue(*system, state, "height");
    const double speed = engine::GetCoordinateSpeed(*system, state, "height");
    const double expected = 0.3 + 0.5 * acceleration * t * t;
    const double steps = static_cast<double>(integrator->stats().steps);
    bound = 2.0 * steps * settings.accuracy * std::max(1.0, std::abs(expected));
    EXPECT_NEAR(height, expected, bound) << "t = " << t;
    EXPECT_NEAR(speed, acceleration * t,
                steps * settings.accuracy * std::max(1.0, std::abs(acceleration * t)))
        << "t = " << t;
    worst = std::max(worst, std::abs(height - expected));
  }
  std::cout << "height: largest error " << worst << " m (bound " << bound << " m)\n";
}

TEST(ClosedFormTest, PrescribedCoordinateFollowsItsFunctionAndDrivesTheRider) {
  opensim::OpenSimParser parser;
  const auto system = parser.Parse(kSliders);
  const int cart = system->FindCoordinate("cart_x");
  ASSERT_GE(cart, 0);
  EXPECT_EQ(system->coordinates()[cart].motion, engine::CoordinateMotion::kPrescribed);
  const engine::IntegratorSettings settings = Settings();
  auto integrator = engine::MakeIntegrator("rk45", *system, settings);
  integrator->SetController(parser.GetController());
  engine::State state = engine::MakeDefaultState(*system);
  // The default state puts the prescribed coordinate on its function (not its default 0).
  EXPECT_NEAR(state.q[cart], Cart(0.0), 1e-15);
  EXPECT_NEAR(state.u[cart], CartSpeed(0.0), 1e-15);
  // The positions are projected onto every constraint after each step, here the prescribed
  // motion cart_x - f(t) = 0, to min(1e-3 accuracy, 1e-10); the speeds exactly (a linear
  // least-squares solve, to rounding of the O(1) speeds: 1e-13 allowed).
  const double projection_tolerance = std::min(1e-3 * settings.accuracy, 1e-10);
  // The rider feels no force along x: its absolute x moves at its initial speed cart_x'(0), so
  // rider_x(t) = rider_x(0) - (cart_x(t) - cart_x(0) - cart_x'(0) t).
  const double rider0 = 0.1;
  double worst_cart = 0.0, worst_rider = 0.0, bound = 0.0;
  for (double t : {0.2, 0.4, 0.6, 0.8, 1.0}) {
    integrator->StepTo(state, t);
    const double steps = static_cast<double>(integrator->stats().steps);
    const double cart_x = engine::GetCoordinateValue(*system, state, "cart_x");
    EXPECT_NEAR(cart_x, Cart(t), projection_tolerance) << "t = " << t;
    EXPECT_NEAR(engine::GetCoordinateSpeed(*system, state, "cart_x"), CartSpeed(t), 1e-13)
        << "t = " << t;
    const double rider = engine::GetCoordinateValue(*system, state, "rider_x");
    const double expected = rider0 - (Cart(t) - Cart(0.0) - CartSpeed(0.0) * t);
    bound = 2.0 * steps * settings.accuracy * std::max(1.0, std::abs(expected));
    EXPECT_NEAR(rider, expected, bound) << "t = " << t;
    const double rider_speed = engine::GetCoordinateSpeed(*system, state, "rider_x");
    EXPECT_NEAR(rider_speed, CartSpeed(0.0) - CartSpeed(t), steps * settings.accuracy)
        << "t = " << t;
    worst_cart = std::max(worst_cart, std::abs(cart_x - Cart(t)));
    worst_rider = std::max(worst_rider, std::abs(rider - expected));
  }
  std::cout << "cart_x: largest error " << worst_cart << " m (tolerance " << projection_tolerance
            << " m); rider_x: largest error " << worst_rider << " m (bound " << bound << " m)\n";
}

}  // namespace
}  // namespace sinew

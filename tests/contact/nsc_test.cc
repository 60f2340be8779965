// The NSC contact method (engine::NscIntegrator) against Coulomb's and Newton's closed forms on
// spheres and a block (contacts from tests/contact/sphere_contact_provider.h): a ball launched
// sliding rolls at 5/7 of its speed from t* = 2 v0 / (7 mu g); a block on an incline sticks
// below the friction angle and slides with g (sin a - mu cos a) above it; a ball dropped with
// restitution e rises to e^2 of its height.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/contact/collision_contact_provider.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/nsc_integrator.h>
#include <sinew/io/osim_reader.h>
#include <sinew/opensim/parser.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <numbers>

#include "contact/contact_models.h"
#include "contact/sphere_contact_provider.h"

namespace sinew::contact {
namespace {

constexpr double kG = 9.80665;

// A free body with no force elements (the spheres are only geometry for the provider).
std::unique_ptr<engine::System> FreeBody(double mass, const Vec3& inertia, const Vec3& gravity) {
  return testing::ParseContactModel(
      testing::FreeBodyContactModel(mass, inertia, gravity, 0.1, {Vec3::Zero()}, ""),
      "nsc_body.osim");
}

using engine::ContactSolverMethod;
// Every closed form below is checked with both impulse solvers.
const ContactSolverMethod kMethods[] = {ContactSolverMethod::kGaussSeidel,
                                        ContactSolverMethod::kApgd};
const char* Name(ContactSolverMethod method) {
  return method == ContactSolverMethod::kApgd ? "APGD" : "Gauss-Seidel";
}

engine::NscSettings TightSolver(ContactSolverMethod method) {
  engine::NscSettings nsc;
  nsc.solver.method = method;
  nsc.solver.max_iterations = 1000;
  nsc.solver.tolerance = 1e-12;
  return nsc;
}

TEST(NscTest, SlidingSphereRollsAtFiveSeventhsOfItsSpeed) {
  // A solid ball (m = 1 kg, r = 0.1 m, I = 2/5 m r^2) resting on the floor, launched at
  // v0 = 1 m/s without spin, mu = 0.4. Coulomb: the slip s = v + w_z r falls at 7/2 mu g
  // until t* = 2 v0 / (7 mu g); then the ball rolls at 5/7 v0 (angular momentum about the
  // contact line is kept).
  // Step size: with the ball resting, each step's normal impulse is m g h and, while it
  // slides, its friction impulse mu m g h: exactly the continuous law integrated over the
  // step, so the sampled slip lies on the continuous line and the final speed is exact (to
  // the solver's tolerance). The step only decides when rolling is seen: in the step in which
  // that line crosses zero, so the first rolling sample is within h after t*, and the line
  // through the sliding samples crosses zero at t* itself.
  constexpr double kM = 1.0, kR = 0.1, kMu = 0.4, kV0 = 1.0, kH = 1e-4;
  for (ContactSolverMethod method : kMethods) {
    SCOPED_TRACE(Name(method));
    auto system = FreeBody(kM, Vec3::Constant(0.4 * kM * kR * kR), Vec3(0, -kG, 0));
    auto provider = std::make_shared<testing::SphereContactProvider>(
        std::vector<testing::TestSphere>{{1, Vec3::Zero(), kR}}, true, kMu, 0.0, 1e-3);
    engine::IntegratorSettings settings;
    settings.step = kH;
    engine::NscIntegrator integrator(*system, provider, settings, TightSolver(method));
    engine::State state = engine::MakeDefaultState(*system);
    engine::SetCoordinateValue(*system, state, "ty", kR);
    engine::SetCoordinateSpeed(*system, state, "tx", kV0);
    auto slip = [](const engine::State& s) {
      return s.bodies[1].v_GB.x() + s.bodies[1].w_GB.z() * kR;
    };
    double t_first_rolling = -1.0, t_line = -1.0, previous = slip(state), worst_residual = 0.0;
    for (int n = 1; n <= 2000; ++n) {
      integrator.StepTo(state, n * kH);
      worst_residual = std::max(worst_residual, integrator.last_step().residual);
      const double s = slip(state);
      if (t_first_rolling < 0.0 && std::abs(s) < 1e-9) {
        t_first_rolling = n * kH;
      } else if (t_first_rolling < 0.0) {
        t_line = n * kH + s / ((previous - s) / kH);  // where the sliding line reaches zero
      }
      previous = s;
    }
    const double t_star = 2.0 * kV0 / (7.0 * kMu * kG);
    const double v = state.bodies[1].v_GB.x();
    EXPECT_GE(t_first_rolling, t_star - 1e-12);
    EXPECT_LE(t_first_rolling, t_star + kH + 1e-12);
    EXPECT_NEAR(t_line, t_star, 2e-3 * t_star);
    EXPECT_NEAR(t_line, t_star, 1e-9 * t_star);  // the samples lie on the continuous line
    EXPECT_NEAR(v, 5.0 / 7.0 * kV0, 2e-3 * kV0);
    EXPECT_NEAR(v, 5.0 / 7.0 * kV0, 1e-9 * kV0);       // the solver's tolerance, 1e-12 m/s
    EXPECT_NEAR(state.bodies[1].p_GB.y(), kR, 1e-12);  // neither sinks nor lifts
    EXPECT_LE(worst_residual, 1e-12);
    std::cout << "nsc rolling (" << Name(method) << "): first rolling sample " << t_first_rolling
              << " s, sliding line " << t_line << " s, t* " << t_star << " s (relative "
              << t_line / t_star - 1 << "); speed " << v << " m/s (relative "
              << v / (5.0 / 7.0 * kV0) - 1 << "); height error " << state.bodies[1].p_GB.y() - kR
              << " m\n";
  }
}

// The downhill displacement of a 1 kg block standing on three small spheres (r = 1 cm, an
// equilateral triangle of 0.1 m radius) on a floor tilted by `angle` (gravity turned instead:
// downhill is +x), mu = 0.5, at 0.5 s and 1 s, and its speeds then.
struct InclineRun {
  double x_half, x_one, v_half, v_one;
};
InclineRun RunIncline(double angle, ContactSolverMethod method) {
  const double r = 0.01, a = 0.1;
  auto system =
      FreeBody(1.0, Vec3(0.01, 0.01, 0.01), kG * Vec3(std::sin(angle), -std::cos(angle), 0));
  std::vector<testing::TestSphere> feet = {{1, Vec3(a, -0.05, 0), r},
                                           {1, Vec3(-a / 2, -0.05, a * std::sqrt(3.0) / 2), r},
                                           {1, Vec3(-a / 2, -0.05, -a * std::sqrt(3.0) / 2), r}};
  auto provider = std::make_shared<testing::SphereContactProvider>(feet, true, 0.5, 0.0, 1e-3);
  engine::IntegratorSettings settings;
  settings.step = 1e-3;
  engine::NscIntegrator integrator(*system, provider, settings, TightSolver(method));
  engine::State state = engine::MakeDefaultState(*system);
  engine::SetCoordinateValue(*system, state, "ty", 0.05 + r);
  InclineRun run{};
  integrator.StepTo(state, 0.5);
  run.x_half = state.bodies[1].p_GB.x();
  run.v_half = state.bodies[1].v_GB.x();
  integrator.StepTo(state, 1.0);
  run.x_one = state.bodies[1].p_GB.x();
  run.v_one = state.bodies[1].v_GB.x();
  return run;
}

TEST(NscTest, BlockSticksBelowTheFrictionAngleAndSlidesAboveIt) {
  constexpr double kMu = 0.5;
  for (ContactSolverMethod method : kMethods) {
    SCOPED_TRACE(Name(method));
    // 20 degrees (tan = 0.364 < 0.5): Coulomb's block sticks. With the solver converged to
    // 1e-12 m/s per step, the drift over 1 s is at most 1e-12 m plus round-off.
    const InclineRun stick = RunIncline(20.0 * std::numbers::pi / 180.0, method);
    EXPECT_LT(std::abs(stick.x_one), 1e-11);
    EXPECT_LT(std::abs(stick.v_one), 1e-11);
    // 35 degrees (tan = 0.700): it slides with a = g (sin a - mu cos a), exactly per step (the
    // friction impulse is mu times the normal one, m g cos a h).
    const double above = 35.0 * std::numbers::pi / 180.0;
    const InclineRun slide = RunIncline(above, method);
    const double acceleration = (slide.v_one - slide.v_half) / 0.5;
    const double closed = kG * (std::sin(above) - kMu * std::cos(above));
    EXPECT_NEAR(acceleration, closed, 1e-9 * closed);
    std::cout << "nsc incline (" << Name(method) << "): drift at 20 deg " << stick.x_one
              << " m, speed " << stick.v_one << " m/s; acceleration at 35 deg " << acceleration
              << " m/s^2 (closed form " << closed << ", relative " << acceleration / closed - 1
              << ")\n";
  }
}

TEST(NscTest, DroppedBallBouncesToRestitutionSquaredOfItsHeight) {
  // A ball (r = 0.1 m) dropped from H = 1 m (its lowest point), restitution e: it leaves the
  // floor at e times its impact speed v = sqrt(2 g H) and rises to e^2 H.
  // Step-size error: the rebound takes the speed at the start of the impact step (at most
  // g h below v: height off by 2 g h / v relative), starts from a gap below h v, and the
  // discrete apex of semi-implicit Euler is within h v of the continuous one.
  constexpr double kR = 0.1, kH0 = 1.0, kStep = 1e-5;
  for (ContactSolverMethod method : kMethods) {
    for (double e : {0.5, 0.8}) {
      auto system = FreeBody(1.0, Vec3::Constant(0.004), Vec3(0, -kG, 0));
      auto provider = std::make_shared<testing::SphereContactProvider>(
          std::vector<testing::TestSphere>{{1, Vec3::Zero(), kR}}, true, 0.3, e, 1e-2);
      engine::IntegratorSettings settings;
      settings.step = kStep;
      engine::NscSettings nsc;  // the default solver settings, as the models use
      nsc.solver.method = method;
      engine::NscIntegrator integrator(*system, provider, settings, nsc);
      engine::State state = engine::MakeDefaultState(*system);
      engine::SetCoordinateValue(*system, state, "ty", kR + kH0);
      const double v = std::sqrt(2 * kG * kH0);
      const double t_apex = v / kG * (1.0 + e);  // fall, then rise
      double apex = 0.0, lowest = 1.0;
      for (int n = 1; n * kStep < t_apex + 0.2 * v / kG; ++n) {
        integrator.StepTo(state, n * kStep);
        const double y = state.bodies[1].p_GB.y() - kR;
        lowest = std::min(lowest, y);
        if (n * kStep > v / kG + 0.01) apex = std::max(apex, y);
      }
      const double tolerance = e * e * kH0 * 2 * kG * kStep / v + 2 * kStep * v;
      EXPECT_NEAR(apex, e * e * kH0, tolerance) << Name(method) << ", e = " << e;
      EXPECT_GT(lowest, -1e-12) << Name(method) << ": the ball never enters the floor";
      std::cout << "nsc bounce (" << Name(method) << ") e = " << e << ": apex " << apex
                << " m (closed form " << e * e * kH0 << ", error " << apex - e * e * kH0
                << ", allowed " << tolerance << "); lowest " << lowest << " m\n";
    }
  }
}

// A ball (m = 1 kg, r = 0.1 m, I = 2/5 m r^2) thrown sideways at v0 = 1 m/s without spin and
// dropped from 0.2 m (its lowest point) onto the floor, mu = 0.6, e = 0.4: it lands slipping,
// bounces and ends rolling. About the contact point on the floor, neither the normal impulse
// (through the centre) nor the friction impulse (on the floor's line) has a moment, and in the
// air nothing acts sideways, so L = m v_x r - I w_z stays m v0 r through every landing, and the
// rolling speed is L / (m r + I / r) = 5/7 v0 whatever mu and e. The stepper keeps L exactly
// when each body's impulse acts at its own surface point: the ball's friction lever is then r
// in every step, also in a landing step that starts with a gap g still open (the envelope); at
// the midway point the lever was r + g / 2 and each landing added g / 2 times its friction
// impulse to L (1.3e-3 relative at h = 1 ms in `simulate` before). What is left is rounding:
// every step updates v and w from impulses of a few N s, a few ulps of m |v| r each, so L
// drifts by at most N steps times 100 eps m r v_max; and the final slip is within the solver's
// tolerance tol, which moves v by at most 2/7 tol from 5/7 L / (m r). Both contact providers:
// the closed-form spheres and Bullet's detector on a parsed ContactSphere and ContactHalfSpace.
TEST(NscTest, DroppedBallRollsAtFiveSeventhsOfItsLandingSpeed) {
  constexpr double kM = 1.0, kR = 0.1, kI = 0.4 * kM * kR * kR, kV0 = 1.0, kDrop = 0.2;
  constexpr double kMu = 0.6, kE = 0.4, kStep = 1e-3, kEnvelope = 2e-3, kTol = 1e-12;
  for (const bool bullet : {false, true}) {
    for (ContactSolverMethod method : kMethods) {
      SCOPED_TRACE(std::string(Name(method)) + (bullet ? ", Bullet" : ", closed-form spheres"));
      std::unique_ptr<engine::System> system;
      std::shared_ptr<const engine::ContactProvider> provider;
      if (bullet) {
        opensim::OpenSimParser parser;
        parser.EnableCollision();
        const model::ModelSpec spec =
            io::ReadOsimString(testing::FreeBodyContactModel(
                                   kM, Vec3::Constant(kI), Vec3(0, -kG, 0), kR, {Vec3::Zero()}, ""),
                               "nsc_landing.osim");
        system = std::make_unique<engine::System>(spec.gravity);
        parser.ParseSpec(*system, spec);
        system->Finalize();
        provider = std::make_shared<CollisionContactProvider>(
            parser.GetCollisionModel(), std::nullopt,
            NscMaterial{.friction = kMu, .restitution = kE, .envelope = kEnvelope});
      } else {
        system = FreeBody(kM, Vec3::Constant(kI), Vec3(0, -kG, 0));
        provider = std::make_shared<testing::SphereContactProvider>(
            std::vector<testing::TestSphere>{{1, Vec3::Zero(), kR}}, true, kMu, kE, kEnvelope);
      }
      engine::IntegratorSettings settings;
      settings.step = kStep;
      engine::NscIntegrator integrator(*system, provider, settings, TightSolver(method));
      engine::State state = engine::MakeDefaultState(*system);
      engine::SetCoordinateValue(*system, state, "ty", kR + kDrop);
      engine::SetCoordinateSpeed(*system, state, "tx", kV0);
      // (A step swaps the state's buffers: read the ball from `state` each time.)
      auto momentum = [&] {
        return kM * state.bodies[1].v_GB.x() * kR - kI * state.bodies[1].w_GB.z();
      };
      const double L0 = momentum();
      double landing_gap = -1.0, landing_friction = 0.0, landing_change = 0.0, drift = 0.0;
      double v_max = 0.0, residual = 0.0;
      int steps = 0;
      for (int n = 1; n * kStep <= 1.5 + 1e-9; ++n, ++steps) {
        const double before = momentum(), gap = state.bodies[1].p_GB.y() - kR;
        const double vx = state.bodies[1].v_GB.x();
        integrator.StepTo(state, n * kStep);
        const engine::BodyState& ball = state.bodies[1];
        v_max = std::max(v_max, ball.v_GB.norm());
        residual = std::max(residual, integrator.last_step().residual);
        drift = std::max(drift, std::abs(momentum() - L0));
        if (landing_gap < 0.0 && integrator.last_step().contacts > 0 &&
            integrator.last_impulses()[0] > 0.0) {
          landing_gap = gap;
          landing_friction = kM * (vx - ball.v_GB.x());
          landing_change = momentum() - before;
        }
      }
      const double rounding =
          steps * 100.0 * std::numeric_limits<double>::epsilon() * kM * kR * v_max;
      ASSERT_GE(landing_gap, 0.0) << "the ball never landed";
      // The landing step conserves L; the old lever would have changed it by g/2 times the
      // friction impulse, far more than the rounding allowed (so the test sees that error).
      EXPECT_NEAR(landing_change, 0.0, rounding);
      EXPECT_GT(0.5 * landing_gap * std::abs(landing_friction), 100.0 * rounding);
      EXPECT_LE(drift, rounding);
      const engine::BodyState& ball = state.bodies[1];
      const double v = ball.v_GB.x(), slip = v + ball.w_GB.z() * kR;
      EXPECT_LE(std::abs(slip), kTol);  // rolling
      EXPECT_NEAR(v, 5.0 / 7.0 * kV0, 2.0 / 7.0 * kTol + 5.0 / 7.0 * rounding / (kM * kR));
      EXPECT_LE(residual, kTol);
      std::cout << "nsc landing (" << Name(method) << (bullet ? ", Bullet" : ", spheres")
                << "): landing step from a gap of " << landing_gap << " m, friction impulse "
                << landing_friction
                << " N s (the midway lever's error g/2 F = " << 0.5 * landing_gap * landing_friction
                << " N m s), L changed by " << landing_change << " N m s; largest drift " << drift
                << " (allowed " << rounding << "); rolling at " << v << " m/s (5/7 v0: relative "
                << v / (5.0 / 7.0 * kV0) - 1 << "), slip " << slip << " m/s\n";
    }
  }
}

TEST(NscTest, BadSettingsAndContactsAreRefused) {
  auto system = FreeBody(1.0, Vec3::Constant(0.004), Vec3(0, -kG, 0));
  auto provider = std::make_shared<testing::SphereContactProvider>(
      std::vector<testing::TestSphere>{{1, Vec3::Zero(), 0.1}}, true, -1.0, 0.0, 1e-2);
  engine::IntegratorSettings settings;
  settings.step = 1e-3;
  EXPECT_THROW(engine::NscIntegrator(*system, nullptr, settings), Error);
  engine::NscSettings bad;
  bad.solver.max_iterations = 0;
  EXPECT_THROW(engine::NscIntegrator(*system, provider, settings, bad), Error);
  // A negative friction coefficient from the provider is named in the error.
  engine::NscIntegrator integrator(*system, provider, settings);
  engine::State state = engine::MakeDefaultState(*system);
  engine::SetCoordinateValue(*system, state, "ty", 0.1);
  try {
    integrator.StepTo(state, 1e-3);
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("friction >= 0"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace sinew::contact

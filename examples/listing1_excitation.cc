// The seed's Listing 1: parse a model with a torque actuator, give the actuator an increasing
// excitation, simulate, and compare with the closed-form answer. Exits 1 when the simulation
// and the closed form differ by more than the integrator's error bound (so ctest fails).
//
//   example_listing1_excitation [MODEL.osim]   (default: chrono's torque-actuator.osim)
#include <sinew/engine/assemble.h>
#include <sinew/engine/integrator.h>
#include <sinew/functions/excitations.h>
#include <sinew/opensim/parser.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

int main(int argc, char** argv) {
  const std::string model =
      argc > 1 ? argv[1] : std::string(SINEW_EXAMPLE_MODELS_DIR) + "/torque-actuator.osim";
  try {
    sinew::OpenSimParser parser;
    std::unique_ptr<sinew::engine::System> system = parser.Parse(model);

    // Listing 1: an excitation rising from 0 with slope 1 per second.
    auto excitation = std::make_shared<sinew::Ramp>(0.0, 1.0);
    parser.SetExcitationFunction("grav", excitation);

    sinew::engine::IntegratorSettings settings;
    settings.accuracy = 1e-9;
    auto integrator = sinew::engine::MakeIntegrator("rk45", *system, settings);
    // The excitations live in the parser's controller, not in the system.
    integrator->SetController(parser.GetController());
    sinew::engine::State state = sinew::engine::MakeDefaultState(*system);
    const double q0 = sinew::engine::GetCoordinateValue(*system, state, "q1");
    // The closed form. rod1 (1 kg, inertia 1 kg m^2 about its mass centre) turns about the pin
    // at 0.5 m from its mass centre: inertia about the pin 1 + 1 * 0.5^2 = 1.25 kg m^2. No
    // gravity. The TorqueActuator puts +9.8 e(t) N m about z on bodyA (ground) and -9.8 e(t)
    // on bodyB (rod1), so q1'' = -9.8 t / 1.25 with q1(0) = q0, q1'(0) = 0:
    //   q1(t) = q0 - 9.8 t^3 / (6 * 1.25).
    const double inertia = 1.25;
    // Error bound: rk45 keeps the estimated local error of every position and speed below
    // `accuracy` (relative, unit floor). Here q1'' depends on t only, so a speed error made at
    // one step grows into a position error of at most (1 s) x itself by t = 1 s: the global
    // error of q1 stays below 2 x accuracy x max(1, |q1|) per step taken.
    double worst = 0.0, bound = 0.0;
    std::printf("%6s %14s %14s %10s\n", "t (s)", "q1 (rad)", "closed form", "error");
    for (double t = 0.25; t <= 1.0 + 1e-12; t += 0.25) {
      integrator->StepTo(state, t);
      const double q = sinew::engine::GetCoordinateValue(*system, state, "q1");
      const double expected = q0 - 9.8 * t * t * t / (6 * inertia);
      const double error = std::abs(q - expected);
      worst = std::max(worst, error);
      bound = 2.0 * settings.accuracy * std::max(1.0, std::abs(expected)) *
              static_cast<double>(integrator->stats().steps);
      std::printf("%6.2f %14.9f %14.9f %10.2e\n", t, q, expected, error);
      if (!(error <= bound)) {
        std::fprintf(stderr,
                     "FAIL: q1(%.2f) differs from the closed form by %.3e rad (bound %.3e)\n", t,
                     error, bound);
        return 1;
      }
    }
    std::printf("largest error %.2e rad in %ld steps (bound %.2e rad)\n", worst,
                integrator->stats().steps, bound);
  } catch (const sinew::Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  return 0;
}

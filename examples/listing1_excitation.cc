// The seed's Listing 1: parse a model with a torque actuator, give the actuator an increasing
// excitation, simulate, and compare with the closed-form answer.
//
//   example_listing1_excitation [MODEL.osim]   (default: chrono's torque-actuator.osim)
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include <sinew/opensim/parser.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/integrator.h>
#include <sinew/functions/excitations.h>

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
    sinew::engine::State state = sinew::engine::MakeDefaultState(*system);
    const double q0 = sinew::engine::GetCoordinateValue(*system, state, "q1");
    // rod1: torque -9.8 t N m about z, inertia about the pin 1 + 1 * 0.5^2 kg m^2.
    const double inertia = 1.25;
    std::printf("%6s %14s %14s\n", "t (s)", "q1 (rad)", "closed form");
    for (double t = 0.25; t <= 1.0 + 1e-12; t += 0.25) {
      integrator->StepTo(state, t);
      const double q = sinew::engine::GetCoordinateValue(*system, state, "q1");
      std::printf("%6.2f %14.9f %14.9f\n", t, q, q0 - 9.8 * t * t * t / (6 * inertia));
    }
  } catch (const sinew::Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  return 0;
}

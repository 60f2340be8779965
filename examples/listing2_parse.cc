// The seed's Listing 2: create a system, set the parser's options, parse a model into the
// system, print the Report, and simulate one second. The model has gravity and no other force,
// so its mechanical energy is conserved: exits 1 when the energy drifts by more than the
// integrator's error bound (so ctest fails).
//
//   example_listing2_parse [MODEL.osim]   (default: chrono's double_pendulum.osim)
#include <sinew/engine/assemble.h>
#include <sinew/engine/energy.h>
#include <sinew/engine/integrator.h>
#include <sinew/opensim/parser.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

namespace {

// A bound on sum_i |dE/dy_i| over the integrator's unknowns y of every body (position p_GB,
// orientation, linear and angular velocity, all of order 1), for speeds up to `max_speed` (m/s)
// and rates up to `max_rate` (rad/s): position m |g|; orientation (a rotation moves the mass
// centre by |p_BCm| and turns I w) m |g| |p_BCm| + |I| max_rate^2; linear velocity m v_Cm;
// angular velocity |I| max_rate + m v_Cm |p_BCm|, with v_Cm <= max_speed + max_rate |p_BCm|.
// Doubled for the four quaternion entries' coupling. In J per unit of y.
double EnergyGradientBound(const sinew::engine::System& system, double max_speed, double max_rate) {
  const double g = system.gravity().norm();
  double bound = 0.0;
  for (int b = 1; b < system.num_bodies(); ++b) {
    const sinew::engine::Body& body = system.bodies()[b];
    const double m = body.mass, r = body.p_BCm.norm(), inertia = body.I_Bcm_B.norm();
    const double v_cm = max_speed + max_rate * r;
    bound +=
        2.0 * (m * g * (1.0 + r) + inertia * max_rate * (1.0 + max_rate) + m * v_cm * (1.0 + r));
  }
  return bound;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string filename =
      argc > 1 ? argv[1] : std::string(SINEW_EXAMPLE_MODELS_DIR) + "/double_pendulum.osim";
  try {
    sinew::engine::System my_system;
    sinew::OpenSimParser parser;
    parser.SetVisualizationType(sinew::VisType::PRIMITIVES);
    parser.EnableCollision();
    parser.SetVerbose(true);
    parser.Parse(my_system, filename);
    my_system.Finalize();

    const sinew::engine::IntegratorSettings settings;
    auto integrator = sinew::engine::MakeIntegrator("rk45", my_system, settings);
    integrator->SetController(parser.GetController());  // the actuators' excitations, if any
    sinew::engine::State state = sinew::engine::MakeDefaultState(my_system);
    const double e0 = sinew::engine::CalcMechanicalEnergy(my_system, state);
    // Step in tenths of a second to record the largest body speeds seen (for the bound).
    double max_speed = 0.0, max_rate = 0.0, drift = 0.0;
    for (int i = 1; i <= 10; ++i) {
      integrator->StepTo(state, 0.1 * i);
      for (int b = 1; b < my_system.num_bodies(); ++b) {
        max_speed = std::max(max_speed, state.bodies[b].v_GB.norm());
        max_rate = std::max(max_rate, state.bodies[b].w_GB.norm());
      }
      drift = std::max(drift, std::abs(sinew::engine::CalcMechanicalEnergy(my_system, state) - e0));
    }
    const double e1 = sinew::engine::CalcMechanicalEnergy(my_system, state);
    const long steps = integrator->stats().steps;
    std::printf("simulated 1 s in %ld steps; energy %.9f J -> %.9f J\n", steps, e0, e1);
    for (const sinew::engine::Coordinate& c : my_system.coordinates()) {
      std::printf("  %-20s %12.6f\n", c.name.c_str(),
                  sinew::engine::GetCoordinateValue(my_system, state, c.name));
    }
    // Error bound: rk45 keeps the estimated local error of every unknown below `accuracy`
    // (relative, unit floor; the unknowns here are of order 1), and the projections onto the
    // joint constraints move positions by at most their tolerance (below `accuracy`). Each
    // step can so change the energy by at most accuracy x sum |dE/dy|.
    const double bound = static_cast<double>(steps) * settings.accuracy *
                         EnergyGradientBound(my_system, max_speed, max_rate);
    std::printf("largest energy drift %.3e J (bound %.3e J)\n", drift, bound);
    if (!(drift <= bound)) {
      std::fprintf(stderr, "FAIL: the energy drifted by %.3e J (bound %.3e J)\n", drift, bound);
      return 1;
    }
  } catch (const sinew::Error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
  return 0;
}

// The seed's Listing 2: create a system, set the parser's options, parse a model into the
// system, print the Report, and simulate one second.
//
//   example_listing2_parse [MODEL.osim]   (default: chrono's double_pendulum.osim)
#include <cstdio>
#include <iostream>
#include <string>

#include <sinew/opensim/parser.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/energy.h>
#include <sinew/engine/integrator.h>

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

    auto integrator = sinew::engine::MakeIntegrator("rk45", my_system, {});
    sinew::engine::State state = sinew::engine::MakeDefaultState(my_system);
    const double e0 = sinew::engine::CalcMechanicalEnergy(my_system, state);
    integrator->StepTo(state, 1.0);
    const double e1 = sinew::engine::CalcMechanicalEnergy(my_system, state);
    std::printf("simulated 1 s in %ld steps; energy %.9f J -> %.9f J\n", integrator->stats().steps,
                e0, e1);
    for (const sinew::engine::Coordinate& c : my_system.coordinates()) {
      std::printf("  %-20s %12.6f\n", c.name.c_str(),
                  sinew::engine::GetCoordinateValue(my_system, state, c.name));
    }
  } catch (const sinew::Error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
  return 0;
}

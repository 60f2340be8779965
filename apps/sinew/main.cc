// sinew: load OpenSim models and simulate them. See README.md and `sinew --help`.
#include <iostream>

#include "apps/sinew/commands.h"
#include <sinew/common/error.h>

int main(int argc, char** argv) {
  CLI::App app{"Sinew: load OpenSim models (.osim) and simulate them in a Cartesian engine"};
  sinew::cli::AddInspectCommand(app);
  sinew::cli::AddSimulateCommand(app);
  sinew::cli::AddExportCommand(app);
  sinew::cli::AddRenderCommand(app);
  sinew::cli::AddKinematicsCommand(app);
  app.require_subcommand(1);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? sinew::cli::kExitOk : sinew::cli::kExitUsage;
  } catch (const sinew::Error& e) {
    std::cerr << "sinew: error: " << e.what() << "\n";
    return sinew::cli::kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "sinew: internal error: " << e.what() << "\n";
    return 3;
  }
  return sinew::cli::kExitOk;
}

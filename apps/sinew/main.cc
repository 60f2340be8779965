// sinew: load OpenSim models and simulate them. See README.md and `sinew --help`.
#include <sinew/common/error.h>

#include <iostream>
#include <string>

#include "apps/sinew/commands.h"
#include "apps/sinew/interrupt_guard.h"

namespace {

// What a command-line mistake prints: CLI11's message, the usage line of the command being
// parsed, and where to find more.
std::string UsageFailure(const CLI::App* app, const CLI::Error& error) {
  const CLI::App* command = app;
  std::string name = "sinew";
  std::string message = error.what();
  if (const std::vector<CLI::App*> parsed = app->get_subcommands(); !parsed.empty()) {
    command = parsed.front();
    name += " " + command->get_name();
  } else if (const std::vector<std::string> rest = app->remaining(); !rest.empty()) {
    // CLI11 says "A subcommand is required" for a misspelt one: name it instead.
    message = "unknown command '" + rest.front() + "' (the commands are";
    for (const CLI::App* sub : app->get_subcommands({})) message += " " + sub->get_name();
    message += ")";
  }
  return "sinew: error: " + message + "\n" + CLI::Formatter().make_usage(command, name) + "Run '" +
         name + " --help' for more information.\n";
}

// "0.1.0 (Release build)": the CMake project version and build type.
std::string VersionText() {
  const std::string build_type = SINEW_BUILD_TYPE;
  return std::string("sinew ") + SINEW_VERSION + " (" +
         (build_type.empty() ? "no build type" : build_type + " build") + ")";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Sinew: load OpenSim models (.osim) and simulate them in a Cartesian engine"};
  app.set_version_flag("--version", VersionText());
  app.failure_message(UsageFailure);
  sinew::cli::AddInspectCommand(app);
  sinew::cli::AddSimulateCommand(app);
  sinew::cli::AddForwardCommand(app);
  sinew::cli::AddExportCommand(app);
  sinew::cli::AddRenderCommand(app);
  sinew::cli::AddKinematicsCommand(app);
  sinew::cli::AddAnalyzeCommand(app);
  app.require_subcommand(1);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? sinew::cli::kExitOk : sinew::cli::kExitUsage;
  } catch (const sinew::cli::ExitRequest& request) {
    return request.code;
  } catch (const sinew::Error& e) {
    std::cerr << "sinew: error: " << e.what() << "\n";
    return sinew::cli::kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "sinew: internal error: " << e.what() << "\n";
    return 3;
  }
  return sinew::cli::kExitOk;
}

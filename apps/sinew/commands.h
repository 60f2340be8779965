// The sinew command-line program: each subcommand lives in its own cmd_*.cc file and registers
// itself on the CLI11 app. A command's callback throws sinew::Error for bad input (exit code 2).
#pragma once

#include <CLI/CLI.hpp>

namespace sinew::cli {

/// Exit codes shared by all commands: 0 for success (and --help, --version); 2 for a
/// command-line mistake (unknown option, bad value, missing argument: the usage is printed) and
/// for bad input (a file that cannot be read or used, --strict refusing a model); 3 for an
/// internal error.
inline constexpr int kExitOk = 0;
inline constexpr int kExitUsage = 2;
inline constexpr int kExitBadInput = 2;

void AddInspectCommand(CLI::App& app);
void AddSimulateCommand(CLI::App& app);
/// `sinew forward`: an OpenSim ForwardTool setup file (cmd_forward.cc).
void AddForwardCommand(CLI::App& app);
/// `sinew export`: glTF (.glb) or HTML viewer of a model and its motion (cmd_export.cc).
void AddExportCommand(CLI::App& app);
/// `sinew render`: a still PNG from the software renderer (cmd_render.cc).
void AddRenderCommand(CLI::App& app);
void AddKinematicsCommand(CLI::App& app);
/// `sinew analyze`: path lengths, lengthening speeds and moment arms over a motion
/// (cmd_analyze.cc).
void AddAnalyzeCommand(CLI::App& app);

}  // namespace sinew::cli

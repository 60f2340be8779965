// The sinew command-line program: each subcommand lives in its own cmd_*.cc file and registers
// itself on the CLI11 app. A command's callback throws sinew::Error for bad input (exit code 2).
#pragma once

#include <CLI/CLI.hpp>

namespace sinew::cli {

/// Exit codes shared by all commands.
inline constexpr int kExitOk = 0;
inline constexpr int kExitUsage = 1;
inline constexpr int kExitBadInput = 2;

void AddInspectCommand(CLI::App& app);
/// `sinew export`: glTF (.glb) or HTML viewer of a model and its motion (cmd_export.cc).
void AddExportCommand(CLI::App& app);
/// `sinew render`: a still PNG from the software renderer (cmd_render.cc).
void AddRenderCommand(CLI::App& app);
void AddKinematicsCommand(CLI::App& app);

}  // namespace sinew::cli

// Checks on the values of command-line options, made before any work is done: numbers that must
// be finite and the size of what a run asks for. Each failure is a CLI11 validation error or a
// sinew::Error: exit code 2 with a message naming the option.
#pragma once

#include <sinew/paths/geometry_path.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <string>
#include <vector>

namespace sinew::cli {

/// The most output rows one `simulate` run may ask for (duration / report interval): 1e8 rows of
/// even a one-coordinate model are gigabytes of text; beyond it a request is a mistake.
inline constexpr double kMaxOutputRows = 1e8;
/// The most integration steps one `simulate` run may ask for through `--step` (duration / step,
/// a lower bound for every integrator): about an hour for a small model.
inline constexpr double kMaxSteps = 1e9;

/// A CLI11 check: the option's text is one finite number (not empty, not nan or inf) that is
/// at least `min`, or above it when `exclusive` (no bound when `min` is -infinity).
CLI::Validator FiniteNumber(double min = -HUGE_VAL, bool exclusive = false);

/// A CLI11 check: the option's text is one whole number from `min` to INT_MAX.
CLI::Validator WholeNumber(int min);

/// Throws sinew::Error unless the run fits the caps above: `duration` / `report_interval` output
/// rows at most kMaxOutputRows and, when `step` > 0, `duration` / `step` steps at most kMaxSteps.
void CheckSimulationSize(double duration, double report_interval, double step);

/// The rule --cylinder-refinement names ("several-wraps", "opensim-4.4" or "always").
paths::CylinderRefinement CylinderRefinementOption(const std::string& text);

/// Adds --cylinder-refinement several-wraps|opensim-4.4|always (into `cylinder_refinement`, checked), as
/// `simulate`, `forward` and `analyze` take it.
void AddCylinderRefinementOption(CLI::App* cmd, std::string& cylinder_refinement);

/// Adds the muscle options `simulate` and `forward` share: --equilibrate-muscles (into
/// `equilibrate`), the repeatable --rename-force-class OLD=NEW (into `renames`) and
/// --cylinder-refinement several-wraps|always (into `cylinder_refinement`, checked).
void AddMuscleOptions(CLI::App* cmd, bool& equilibrate, std::vector<std::string>& renames,
                      std::string& cylinder_refinement);

}  // namespace sinew::cli

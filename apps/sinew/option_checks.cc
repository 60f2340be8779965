#include "apps/sinew/option_checks.h"

#include <sinew/common/error.h>
#include <sinew/common/text.h>

#include <cmath>
#include <limits>
#include <sstream>

#include "apps/sinew/notices.h"

namespace sinew::cli {

CLI::Validator FiniteNumber(double min, bool exclusive) {
  const std::string bound =
      std::isinf(min) ? std::string() : std::string(exclusive ? " > " : " >= ") + ShowNumber(min);
  return CLI::Validator(
      [min, exclusive, bound](std::string& text) -> std::string {
        double value = 0;
        if (!ParseNumber(TrimSpace(text), &value) || !std::isfinite(value) ||
            (exclusive ? !(value > min) : !(value >= min))) {
          return "expects a finite number" + bound + ", not '" + text + "'";
        }
        return "";
      },
      "NUMBER" + bound);
}

CLI::Validator WholeNumber(int min) {
  const std::string bound = " >= " + std::to_string(min);
  return CLI::Validator(
      [min, bound](std::string& text) -> std::string {
        const std::string trimmed(TrimSpace(text));
        double value = 0;
        if (trimmed.find_first_not_of("+-0123456789") != std::string::npos ||
            !ParseNumber(trimmed, &value) || !(value >= min) ||
            !(value <= std::numeric_limits<int>::max())) {
          return "expects a whole number" + bound + ", not '" + text + "'";
        }
        return "";
      },
      "INTEGER" + bound);
}

void CheckSimulationSize(double duration, double report_interval, double step) {
  const double rows = duration / report_interval;
  if (!(rows <= kMaxOutputRows)) {
    throw Error("--duration " + ShowNumber(duration) + " with --report-interval " +
                ShowNumber(report_interval) + " asks for " + ShowNumber(rows) +
                " output rows; at most " + ShowNumber(kMaxOutputRows) +
                " are allowed (make the report interval longer)");
  }
  if (step > 0 && !(duration / step <= kMaxSteps)) {
    throw Error("--duration " + ShowNumber(duration) + " with --step " + ShowNumber(step) +
                " asks for at least " + ShowNumber(duration / step) +
                " integration steps; at most " + ShowNumber(kMaxSteps) +
                " are allowed (make the step longer)");
  }
}

paths::CylinderRefinement CylinderRefinementOption(const std::string& text) {
  return paths::FindCylinderRefinement(text).value_or(paths::CylinderRefinement::kSeveralWraps);
}

void AddCylinderRefinementOption(CLI::App* cmd, std::string& cylinder_refinement) {
  cmd->add_option("--cylinder-refinement", cylinder_refinement,
                  "When and how a WrapCylinder refines its tangent points: several-wraps "
                  "(OpenSim 4.4.1 and later: only on paths with two or more wrap objects; the "
                  "default), opensim-4.4 (the same paths, the second tangent point checked as "
                  "OpenSim 4.4.0 and earlier did) or always (every OpenSim before 4.4, to "
                  "compare with results it wrote)")
      ->check(CLI::IsMember({"several-wraps", "opensim-4.4", "always"}));
}

void AddMuscleOptions(CLI::App* cmd, bool& equilibrate, std::vector<std::string>& renames,
                      std::string& cylinder_refinement) {
  cmd->add_flag("--equilibrate-muscles", equilibrate,
                "Start every muscle's fiber at muscle-tendon equilibrium for its activation "
                "(OpenSim's equilibrateMuscles); otherwise default_fiber_length or the "
                "initial-states file's fiber_length");
  cmd->add_option("--rename-force-class", renames,
                  "OLD=NEW: read forces of class OLD as class NEW (OpenSim's renameType; "
                  "OpenSim's forward tests read Thelen2003Muscle=Thelen2003Muscle_Deprecated)");
  AddCylinderRefinementOption(cmd, cylinder_refinement);
}

}  // namespace sinew::cli

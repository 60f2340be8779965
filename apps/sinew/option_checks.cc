#include "apps/sinew/option_checks.h"

#include <sinew/common/error.h>
#include <sinew/common/text.h>

#include <cmath>
#include <sstream>

namespace sinew::cli {
namespace {

std::string Show(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

}  // namespace

CLI::Validator FiniteNumber(double min, bool exclusive) {
  const std::string bound =
      std::isinf(min) ? std::string() : std::string(exclusive ? " > " : " >= ") + Show(min);
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

void CheckSimulationSize(double duration, double report_interval, double step) {
  const double rows = duration / report_interval;
  if (!(rows <= kMaxOutputRows)) {
    throw Error("--duration " + Show(duration) + " with --report-interval " +
                Show(report_interval) + " asks for " + Show(rows) + " output rows; at most " +
                Show(kMaxOutputRows) + " are allowed (make the report interval longer)");
  }
  if (step > 0 && !(duration / step <= kMaxSteps)) {
    throw Error("--duration " + Show(duration) + " with --step " + Show(step) +
                " asks for at least " + Show(duration / step) + " integration steps; at most " +
                Show(kMaxSteps) + " are allowed (make the step longer)");
  }
}

}  // namespace sinew::cli

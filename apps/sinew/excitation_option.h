// The `--excitation NAME=KIND:ARGS` option of `sinew simulate`.
#pragma once

#include <sinew/functions/function.h>

#include <string>
#include <utility>

namespace sinew::cli {

/// Parses "NAME=constant:V", "NAME=ramp:START,SLOPE" (0 before START, then SLOPE per second)
/// or "NAME=sine:AMPLITUDE,FREQUENCY_HZ,PHASE" (phase in rad) into the actuator name and its
/// excitation function. Throws sinew::Error naming the option for anything else.
std::pair<std::string, functions::FunctionPtr> ParseExcitationOption(const std::string& option);

}  // namespace sinew::cli

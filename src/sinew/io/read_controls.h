// Reading OpenSim ControlSet files (`*_controls.xml`) into excitation functions.
#pragma once

#include <sinew/functions/function.h>

#include <map>
#include <string>

namespace sinew::io {

/// The controls of a ControlSet file, by actuator name: a control named "X.excitation" (or
/// "X") drives actuator X. ControlLinear controls become ControlLinear functions (use_steps
/// and extrapolate honoured), ControlConstant controls Constant functions of their `value`.
/// A file whose name contains ".sto" is read as OpenSim reads it, as a storage table: each
/// column a ControlLinear (linear, extrapolated) through its value at every row.
/// Throws sinew::Error (file, line, control) for malformed files or unsupported control types.
std::map<std::string, functions::FunctionPtr> ReadControlSet(const std::string& file);

/// As ReadControlSet, from the XML text of a ControlSet file; `file` names it in messages.
std::map<std::string, functions::FunctionPtr> ParseControlSet(std::string text,
                                                              const std::string& file);

}  // namespace sinew::io

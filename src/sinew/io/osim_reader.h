// Reading OpenSim model files (.osim, format versions 1.9 = 10901 to 4.6 = 40600) into the spec.
#pragma once

#include <sinew/model/model_spec.h>

#include <string>

namespace sinew::io {

/// Reads the .osim file `file` into a ModelSpec: ground (bodies[0]), bodies, offset frames
/// (3.x joint offsets become frames named as OpenSim 4 names them), joints with their frames
/// resolved to bodies, coordinates, constraints, forces with geometry paths, markers, contact
/// geometry, controllers and everything else as generic elements. Anything approximated or
/// ignored is listed in ModelSpec::warnings.
/// Throws sinew::Error naming the file, the line and the component path for malformed input.
model::ModelSpec ReadOsim(const std::string& file);

/// As ReadOsim, from text held in memory; `file` names it in messages (tests, fuzzing).
model::ModelSpec ReadOsimString(std::string text, const std::string& file);

}  // namespace sinew::io

// Reading OpenSim model files (.osim, format versions 1.9 = 10901 to 4.6 = 40600) into the spec.
#pragma once

#include <sinew/model/model_spec.h>

#include <string>
#include <vector>

namespace sinew::io {

/// ForceSet files a tool adds to the model it reads (OpenSim's `force_set_files` and
/// `replace_force_set` of a setup file, e.g. CMC's reserve and residual actuators).
struct ForceSetFiles {
  std::vector<std::string> files;  ///< `<ForceSet>` files (bare or in an OpenSimDocument).
  bool replace = false;            ///< true: the model's own forces are dropped first.
};

/// Reads the .osim file `file` into a ModelSpec: ground (bodies[0]), bodies, offset frames
/// (3.x joint offsets become frames named as OpenSim 4 names them), joints with their frames
/// resolved to bodies, coordinates, constraints, forces with geometry paths, markers, contact
/// geometry, controllers and everything else as generic elements. Anything approximated or
/// ignored is listed in ModelSpec::warnings.
/// Throws sinew::Error naming the file, the line and the component path for malformed input.
model::ModelSpec ReadOsim(const std::string& file);

/// As ReadOsim, with the forces of `force_sets` appended to (or replacing) the model's ForceSet,
/// each as if the model's file held it: named /forceset/<name>, its bodies and coordinates
/// those of the model, errors naming the ForceSet file and line. A `<defaults>` object of a
/// ForceSet file gives its values to the objects of the same class that leave them out, as in
/// OpenSim. Throws sinew::Error as ReadOsim does, and for a file that is not a ForceSet.
model::ModelSpec ReadOsim(const std::string& file, const ForceSetFiles& force_sets);

/// As ReadOsim, from text held in memory; `file` names it in messages (tests, fuzzing).
model::ModelSpec ReadOsimString(std::string text, const std::string& file);

}  // namespace sinew::io

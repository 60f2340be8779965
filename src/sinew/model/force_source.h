// Which file a force's properties were read from, for the file:line of its errors.
#pragma once

#include <sinew/model/model_spec.h>

#include <string>

namespace sinew::model {

/// The file `force` was read from: the model's, or the ForceSet or ExternalLoads file that held
/// it (ForceSpec::where); the model's file for a force made in code, which has no location.
inline const std::string& SourceFile(const ModelSpec& spec, const ForceSpec& force) {
  return force.where.file.empty() ? spec.file : force.where.file;
}

}  // namespace sinew::model

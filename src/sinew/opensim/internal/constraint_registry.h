// Spec -> engine for OpenSim's constraint classes: one registry from OpenSim class name to the
// builder that makes the engine constraint, and to the coordinates whose joints must be
// parameterized for it. A new constraint type is one entry here; the builder, the parser, the
// list of what is not simulated and the Report all read this table.
#pragma once

#include <sinew/engine/constraint.h>
#include <sinew/model/element_values.h>
#include <sinew/model/model_spec.h>

#include <memory>
#include <string>
#include <vector>

namespace sinew::opensim::internal {

/// What a constraint builder reads: the spec, the constraint, its property values, and the maps
/// from spec bodies and coordinates to engine ones.
struct ConstraintBuildInput {
  const model::ModelSpec& spec;
  const model::ConstraintSpec& constraint;
  const model::ElementValues& values;
  const std::vector<int>& body_map;        ///< spec body index -> engine body index
  const std::vector<int>& coordinate_map;  ///< spec coordinate index -> engine coordinate index
};

/// How one OpenSim constraint class is built.
struct ConstraintType {
  /// Makes the engine constraint. Throws sinew::Error (file, line, constraint path) for
  /// unknown or unsuitable coordinates and malformed properties.
  std::shared_ptr<engine::Constraint> (*build)(const ConstraintBuildInput& input);
  /// The spec coordinates whose speeds the constraint uses: their joints must be built in the
  /// parameterized form (engine::JointForm::kParameterized).
  std::vector<int> (*coordinates)(const model::ConstraintSpec& constraint);
};

/// The entry for OpenSim class `opensim_class`, or null when Sinew does not simulate it.
const ConstraintType* FindConstraintType(const std::string& opensim_class);

/// The engine constraint of `constraint`, whose class must have a registry entry.
std::shared_ptr<engine::Constraint> BuildConstraint(const model::ModelSpec& spec,
                                                    const model::ConstraintSpec& constraint,
                                                    const std::vector<int>& body_map,
                                                    const std::vector<int>& coordinate_map);

}  // namespace sinew::opensim::internal

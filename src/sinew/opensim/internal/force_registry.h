// Spec -> engine for OpenSim's force classes: one registry from OpenSim class name to the
// builder that makes the engine force element. A new force type is one entry here (and its
// element in forces/); the parser, the list of what is not simulated and the Report all read
// this table.
#pragma once

#include <sinew/common/error.h>
#include <sinew/engine/force_element.h>
#include <sinew/io/external_loads.h>
#include <sinew/model/element_values.h>
#include <sinew/model/model_spec.h>

#include <memory>
#include <string>
#include <vector>

namespace sinew::opensim::internal {

/// What a force builder reads: the spec, the force, its property values, and the maps from
/// spec bodies and coordinates to engine ones.
struct ForceBuildInput {
  const model::ModelSpec& spec;
  const model::ForceSpec& force;
  const model::ElementValues& values;
  const std::vector<int>& body_map;        ///< spec body index -> engine body index
  const std::vector<int>& coordinate_map;  ///< spec coordinate index -> engine coordinate index
  /// The ExternalLoads file the force comes from (its data), or null for a model's own force.
  const io::ExternalLoads* external_loads = nullptr;
  /// Where a builder notes what it read leniently, as OpenSim would (may be null).
  Diagnostics* notes = nullptr;
};

/// How one OpenSim force class is built.
struct ForceType {
  /// Makes the engine element. Throws sinew::Error (file, line, force path) for unknown bodies
  /// or coordinates or malformed properties.
  std::shared_ptr<engine::ForceElement> (*build)(const ForceBuildInput& input);
  /// True for actuators (forces::Actuator: one excitation input, listed with its source).
  bool actuator = false;
};

/// The entry for OpenSim class `opensim_class`, or null when Sinew does not simulate it.
const ForceType* FindForceType(const std::string& opensim_class);

/// The engine element of `force`, whose class must have a registry entry.
/// `external_loads` and `notes` as in ForceBuildInput.
std::shared_ptr<engine::ForceElement> BuildForce(const model::ModelSpec& spec,
                                                 const model::ForceSpec& force,
                                                 const std::vector<int>& body_map,
                                                 const std::vector<int>& coordinate_map,
                                                 const io::ExternalLoads* external_loads = nullptr,
                                                 Diagnostics* notes = nullptr);

/// The last segment of a socket path ("/bodyset/rod1" -> "rod1"), or the name itself.
std::string LastPathSegment(const std::string& path);

}  // namespace sinew::opensim::internal

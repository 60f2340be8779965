// The seed's collision system from a parsed model (OpenSimParser::EnableCollision): the
// collision model (the seed's cylinders, OpenSim's contact geometry, the
// environment, materials) and, for the SMC contact method, its force element.
#pragma once

#include <sinew/contact/collision_model.h>
#include <sinew/engine/system.h>
#include <sinew/model/model_spec.h>
#include <sinew/opensim/collision_settings.h>
#include <sinew/opensim/report.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sinew::opensim::internal {

/// The collision model of `spec` (spec body indices). Contact geometry a simulated contact
/// force of the file names (unless the force is in `disabled_forces`) is left to that force, other
/// geometry kinds are Report warnings. A ContactMesh's file is searched as ReadContactMesh says,
/// `geometry_dirs` after the model's folders. Throws sinew::Error (file, line, component) for a bad
/// material or an unknown override name.
contact::CollisionModel BuildCollision(const model::ModelSpec& spec,
                                       const opensim::CollisionSettings& settings,
                                       const std::vector<std::string>& disabled_forces,
                                       const std::vector<std::string>& geometry_dirs,
                                       Report& report);

/// Whether any of `model`'s materials has a tangential stiffness kt > 0 (SMC then keeps each
/// contact's tangential displacement).
bool HasTangentialStiffness(const contact::CollisionModel& model);

/// The SMC-only material parameters (young_modulus, poisson_ratio, kn, gn, kt, gt) that any of
/// `model`'s materials sets away from its default, in that order: NSC ignores them.
std::vector<std::string> SmcOnlyParametersSet(const contact::CollisionModel& model);

/// Adds the SMC force element "smc_contact" over `model` (spec indices, mapped through
/// `body_map`) to `system`; pairs that overlap in the default pose are left out.
void AddSmoothContact(engine::System& system, const model::ModelSpec& spec,
                      const contact::CollisionModel& model, const std::vector<int>& body_map,
                      double slip_speed, Report& report);

}  // namespace sinew::opensim::internal

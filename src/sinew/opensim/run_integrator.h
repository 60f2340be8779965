// The integrator a run of a parsed model needs. With collision enabled and the NSC contact
// method (the seed's non-smooth contact), that is engine::NscIntegrator over the parser's
// collision model: NSC is a time-stepping scheme of its own, not a force, so the integrator the
// caller names does not apply. Otherwise it is the named one (engine::MakeIntegrator); SMC
// contact is a force element and acts in every integrator. One function, so that the CLI and
// Python run the same thing.
#pragma once

#include <sinew/engine/integrator.h>
#include <sinew/engine/system.h>
#include <sinew/opensim/parser.h>

#include <memory>
#include <string>

namespace sinew::opensim {

/// The fixed step of an NSC run when `settings.step` is not > 0 (s), the seed's.
inline constexpr double kDefaultNscStep = 1e-3;

/// True when runs of what `parser` built step with NSC (collision enabled, NSC method).
bool UsesNscContact(const OpenSimParser& parser);

/// For NSC (UsesNscContact): engine::NscIntegrator at `settings.step` (kDefaultNscStep when not
/// > 0) with the parser's NSC settings (OpenSimParser::SetNscSettings) over its collision model
/// (its ground plane with the rest of the environment), each pair's friction and restitution
/// combined from its shapes' materials, the pairs overlapping at the default pose left out.
/// Otherwise engine::MakeIntegrator(`name`, ...). `system` is what `parser` built; both must
/// outlive the integrator. Throws sinew::Error as MakeIntegrator does.
std::unique_ptr<engine::Integrator> MakeRunIntegrator(const std::string& name,
                                                      const engine::System& system,
                                                      const OpenSimParser& parser,
                                                      const engine::IntegratorSettings& settings);

}  // namespace sinew::opensim

#include <sinew/contact/collision_contact_provider.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/nsc_integrator.h>
#include <sinew/opensim/run_integrator.h>

#include <optional>
#include <utility>
#include <vector>

namespace sinew::opensim {

bool UsesNscContact(const OpenSimParser& parser) {
  return parser.IsCollisionEnabled() && parser.GetContactMethod() == ContactMethod::kNsc;
}

std::unique_ptr<engine::Integrator> MakeRunIntegrator(const std::string& name,
                                                      const engine::System& system,
                                                      const OpenSimParser& parser,
                                                      const engine::IntegratorSettings& settings) {
  if (!UsesNscContact(parser)) return engine::MakeIntegrator(name, system, settings);
  // The ground plane stays in the environment with its own material (the detector's envelope
  // covers every shape alike).
  const contact::CollisionModel& model = parser.GetCollisionModel();
  // The default material's friction and restitution; shapes with their own keep theirs.
  const contact::CollisionMaterial& material = model.materials.front();
  const contact::NscMaterial nsc{.friction = material.friction,
                                 .restitution = material.restitution};
  std::vector<Transform> X_GB_rest;
  contact::GatherBodyPoses(engine::MakeDefaultState(system), X_GB_rest);
  auto provider =
      std::make_shared<contact::CollisionContactProvider>(model, std::nullopt, nsc, X_GB_rest);
  engine::IntegratorSettings nsc_settings = settings;
  if (!(nsc_settings.step > 0.0)) nsc_settings.step = kDefaultNscStep;
  return std::make_unique<engine::NscIntegrator>(system, std::move(provider), nsc_settings,
                                                 parser.GetNscSettings());
}

}  // namespace sinew::opensim

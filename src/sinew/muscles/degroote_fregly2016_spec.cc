#include <sinew/common/error.h>
#include <sinew/model/element_values.h>
#include <sinew/model/force_source.h>
#include <sinew/muscles/degroote_fregly2016_spec.h>
#include <sinew/muscles/internal/muscle_base_properties.h>

namespace sinew::muscles {

DeGrooteFregly2016Muscle ReadDeGrooteFregly2016Muscle(const model::ModelSpec& spec,
                                                      const model::ForceSpec& force) {
  const model::ElementValues v(force.element, model::SourceFile(spec, force), force.path);
  DeGrooteFregly2016Parameters p;
  p.name = force.path;
  if (v.Double("optimal_force", 1.0) != 1.0) {
    v.Fail(
        "optimal_force is ignored by DeGrooteFregly2016Muscle (OpenSim refuses a value other "
        "than 1): use max_isometric_force");
  }
  internal::ReadMuscleBaseProperties(v, &p);
  p.activation_time_constant = v.Double("activation_time_constant", p.activation_time_constant);
  p.deactivation_time_constant =
      v.Double("deactivation_time_constant", p.deactivation_time_constant);
  p.default_activation = v.Double("default_activation", p.default_activation);
  p.default_normalized_tendon_force =
      v.Double("default_normalized_tendon_force", p.default_normalized_tendon_force);
  p.active_force_width_scale = v.Double("active_force_width_scale", p.active_force_width_scale);
  p.fiber_damping = v.Double("fiber_damping", p.fiber_damping);
  p.ignore_passive_fiber_force = v.Bool("ignore_passive_fiber_force", p.ignore_passive_fiber_force);
  p.passive_fiber_strain_at_one_norm_force =
      v.Double("passive_fiber_strain_at_one_norm_force", p.passive_fiber_strain_at_one_norm_force);
  p.tendon_strain_at_one_norm_force =
      v.Double("tendon_strain_at_one_norm_force", p.tendon_strain_at_one_norm_force);
  p.tendon_compliance_dynamics_mode =
      v.String("tendon_compliance_dynamics_mode", p.tendon_compliance_dynamics_mode);
  p.activation_dynamics_smoothing =
      v.Double("activation_dynamics_smoothing", p.activation_dynamics_smoothing);
  try {
    return DeGrooteFregly2016Muscle(p);
  } catch (const Error& error) {
    v.Fail(error.message());
  }
}

}  // namespace sinew::muscles

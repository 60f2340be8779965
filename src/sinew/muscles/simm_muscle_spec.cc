#include <sinew/common/error.h>
#include <sinew/model/force_source.h>
#include <sinew/muscles/simm_muscle_spec.h>

#include <string>
#include <utility>

namespace sinew::muscles {
namespace {

// Files of format 20301 and older name pennation_angle_at_optimal `pennation_angle` (OpenSim's
// Muscle::updateFromXMLNode renames it).
constexpr int kPennationRenamedVersion = 20301;

// A Function-valued property the reader kept (io's FunctionProperties), or nullptr.
functions::FunctionPtr CurveOf(const model::ForceSpec& force, const std::string& property) {
  const auto it = force.functions.find(property);
  return it == force.functions.end() || it->second.empty() ? nullptr : it->second.front();
}

// The model built from its parameters, a message-only error given the file, line and force.
template <class Model, class Parameters>
Model Make(const model::ElementValues& v, Parameters parameters) {
  try {
    return Model(std::move(parameters));
  } catch (const Error& error) {
    if (!error.where().file.empty()) throw;
    v.Fail(error.message());
  }
}

}  // namespace

MuscleParameters ReadMuscleParameters(int version, const model::ElementValues& v) {
  MuscleParameters m;
  m.max_isometric_force = v.Double("max_isometric_force", m.max_isometric_force);
  m.optimal_fiber_length = v.Double("optimal_fiber_length", m.optimal_fiber_length);
  m.tendon_slack_length = v.Double("tendon_slack_length", m.tendon_slack_length);
  const bool old_name = version <= kPennationRenamedVersion &&
                        !v.Has("pennation_angle_at_optimal") && v.Has("pennation_angle");
  m.pennation_angle_at_optimal = v.Double(
      old_name ? "pennation_angle" : "pennation_angle_at_optimal", m.pennation_angle_at_optimal);
  m.max_contraction_velocity = v.Double("max_contraction_velocity", m.max_contraction_velocity);
  return m;
}

Schutte1993Muscle ReadSchutte1993Muscle(const model::ModelSpec& spec,
                                        const model::ForceSpec& force) {
  const model::ElementValues v(force.element, model::SourceFile(spec, force), force.path);
  // OpenSim's ActivationFiberLengthMuscle_Deprecated throws for either flag.
  for (const char* flag : {"ignore_tendon_compliance", "ignore_activation_dynamics"}) {
    if (v.Bool(flag, false)) {
      const model::Element* property = force.element.Child(flag);
      v.Fail(std::string(flag) + " is true: OpenSim's " + force.type +
                 " does not implement it (and refuses the model)",
             property ? property->line : 0);
    }
  }
  Schutte1993Parameters p;
  p.muscle = ReadMuscleParameters(force.version, v);
  p.time_scale = v.Double("time_scale", p.time_scale);
  p.activation1 = v.Double("activation1", p.activation1);
  p.activation2 = v.Double("activation2", p.activation2);
  p.damping = v.Double("damping", p.damping);
  p.tendon_force_length_curve = CurveOf(force, "tendon_force_length_curve");
  p.active_force_length_curve = CurveOf(force, "active_force_length_curve");
  p.passive_force_length_curve = CurveOf(force, "passive_force_length_curve");
  return Make<Schutte1993Muscle>(v, std::move(p));
}

RigidTendonMuscle ReadRigidTendonMuscle(const model::ModelSpec& spec,
                                        const model::ForceSpec& force) {
  const model::ElementValues v(force.element, model::SourceFile(spec, force), force.path);
  RigidTendonParameters p;
  p.muscle = ReadMuscleParameters(force.version, v);
  p.active_force_length_curve = CurveOf(force, "active_force_length_curve");
  p.passive_force_length_curve = CurveOf(force, "passive_force_length_curve");
  p.force_velocity_curve = CurveOf(force, "force_velocity_curve");
  return Make<RigidTendonMuscle>(v, std::move(p));
}

}  // namespace sinew::muscles

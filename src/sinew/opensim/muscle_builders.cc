// Builders of the forces that pull along a GeometryPath: PathActuator and the muscle classes,
// each a muscles::PathActuator with its tension model. The properties keep OpenSim's names
// and defaults (Muscle.cpp, Thelen2003Muscle.cpp, ActivationFiberLengthMuscle.cpp).
#include <sinew/model/element_values.h>
#include <sinew/muscles/blankevoort_ligament.h>
#include <sinew/muscles/degroote_fregly2016_spec.h>
#include <sinew/muscles/degroote_fregly2016_tension.h>
#include <sinew/muscles/millard2012_spec.h>
#include <sinew/muscles/millard2012_tension.h>
#include <sinew/muscles/path_actuator.h>
#include <sinew/muscles/path_spring.h>
#include <sinew/muscles/simm_muscle_spec.h>
#include <sinew/muscles/thelen2003_muscle.h>
#include <sinew/muscles/thelen2003_muscle_deprecated.h>
#include <sinew/opensim/internal/force_registry.h>

#include <limits>
#include <optional>

namespace sinew::opensim::internal {
namespace {

// The force's path on the engine system; a path force without a GeometryPath or a
// FunctionBasedPath is an error.
muscles::EnginePath MakeEnginePath(const ForceBuildInput& in) {
  if (!in.force.geometry_path && !in.force.function_based_path) {
    in.values.Fail(
        "has no GeometryPath or FunctionBasedPath (other path kinds, such as "
        "Scholz2015GeometryPath, are not simulated)");
  }
  return muscles::EnginePath(paths::GeometryPath(in.spec, in.force, in.cylinder_refinement),
                             static_cast<int>(in.spec.bodies.size()),
                             static_cast<int>(in.spec.coordinates.size()), in.body_map,
                             in.coordinate_map);
}

// The actuator, with min_control / max_control kept for reporting (they do not clamp).
std::shared_ptr<engine::ForceElement> MakePathActuator(
    const ForceBuildInput& in, double optimal_force,
    std::shared_ptr<const muscles::TensionModel> model, double default_min_control,
    double default_max_control) {
  auto actuator = std::make_shared<muscles::PathActuator>(
      in.force.name, optimal_force, MakeEnginePath(in), std::move(model), in.equilibrate_muscles);
  try {
    actuator->SetControlRange(in.values.Bound("min_control", default_min_control),
                              in.values.Bound("max_control", default_max_control));
  } catch (const Error& error) {
    in.values.Fail(error.message());
  }
  return actuator;
}

// OpenSim's Thelen2003Muscle reads ignore_tendon_compliance and ignore_activation_dynamics
// but its equations never look at them; Sinew does the same, and says so.
void NoteIgnoredFlags(const ForceBuildInput& in) {
  if (!in.notes) return;
  for (const char* flag : {"ignore_tendon_compliance", "ignore_activation_dynamics"}) {
    if (in.values.Bool(flag, false)) {
      in.notes->push_back({in.force.where, in.force.path,
                           std::string(flag) + " is true, but " + in.force.type +
                               " ignores it (as OpenSim's does): the tendon stays compliant "
                               "and activation dynamic"});
    }
  }
}

}  // namespace

std::shared_ptr<engine::ForceElement> BuildPathActuator(const ForceBuildInput& in) {
  const double optimal_force = in.values.Double("optimal_force", 1.0);
  constexpr double kInf = std::numeric_limits<double>::infinity();
  return MakePathActuator(in, optimal_force,
                          std::make_shared<muscles::IdealPathTension>(optimal_force), -kInf, kInf);
}

std::shared_ptr<engine::ForceElement> BuildPathSpring(const ForceBuildInput& in) {
  const model::ElementValues& v = in.values;
  // OpenSim's defaults are NaN: a spring without its properties is an error here.
  for (const char* property : {"resting_length", "stiffness", "dissipation"}) {
    if (!v.Has(property)) v.Fail(std::string("PathSpring needs <") + property + ">");
  }
  return std::make_shared<muscles::PathSpring>(
      in.force.name, MakeEnginePath(in), v.Double("resting_length", 0.0),
      v.Double("stiffness", 0.0), v.Double("dissipation", 0.0));
}

// OpenSim's defaults except slack_length, whose default 0 makes the strain infinite: it must be
// given. Bad values are refused with the file, line and component.
std::shared_ptr<engine::ForceElement> BuildBlankevoortLigament(const ForceBuildInput& in) {
  const model::ElementValues& v = in.values;
  if (!v.Has("slack_length")) v.Fail("Blankevoort1991Ligament needs <slack_length>");
  muscles::BlankevoortParameters p;
  p.linear_stiffness = v.Double("linear_stiffness", p.linear_stiffness);
  p.transition_strain = v.Double("transition_strain", p.transition_strain);
  p.damping_coefficient = v.Double("damping_coefficient", p.damping_coefficient);
  p.slack_length = v.Double("slack_length", p.slack_length);
  if (const auto bad = muscles::FindBadParameter(p)) {
    const model::Element* property = in.force.element.Child(bad->property);
    v.Fail(bad->message, property ? property->line : 0);
  }
  return std::make_shared<muscles::BlankevoortLigament>(in.force.name, MakeEnginePath(in), p);
}

std::shared_ptr<engine::ForceElement> BuildThelen2003Muscle(const ForceBuildInput& in) {
  const model::ElementValues& v = in.values;
  muscles::Thelen2003Parameters p;
  p.muscle = muscles::ReadMuscleParameters(in.force.version, v);
  muscles::Thelen2003CurveParameters& c = p.curves;
  c.FmaxTendonStrain = v.Double("FmaxTendonStrain", c.FmaxTendonStrain);
  c.FmaxMuscleStrain = v.Double("FmaxMuscleStrain", c.FmaxMuscleStrain);
  c.KshapeActive = v.Double("KshapeActive", c.KshapeActive);
  c.KshapePassive = v.Double("KshapePassive", c.KshapePassive);
  c.Af = v.Double("Af", c.Af);
  c.Flen = v.Double("Flen", c.Flen);
  c.fv_linear_extrap_threshold =
      v.Double("fv_linear_extrap_threshold", c.fv_linear_extrap_threshold);
  muscles::FirstOrderActivation& a = p.activation;
  a.activation_time_constant = v.Double("activation_time_constant", a.activation_time_constant);
  a.deactivation_time_constant =
      v.Double("deactivation_time_constant", a.deactivation_time_constant);
  a.minimum_activation = v.Double("minimum_activation", a.minimum_activation);
  p.maximum_pennation_angle = v.Double("maximum_pennation_angle", p.maximum_pennation_angle);
  p.default_activation = v.Double("default_activation", p.default_activation);
  p.default_fiber_length = v.Double("default_fiber_length", p.muscle.optimal_fiber_length);
  NoteIgnoredFlags(in);
  std::shared_ptr<const muscles::Thelen2003Muscle> model;
  try {
    model = std::make_shared<muscles::Thelen2003Muscle>(p);
  } catch (const Error& error) {
    v.Fail(error.message());
  }
  // A Muscle's controls range over [0, 1]; Thelen's minimum is its minimum activation.
  return MakePathActuator(in, v.Double("optimal_force", 1.0), std::move(model),
                          a.minimum_activation, 1.0);
}

std::shared_ptr<engine::ForceElement> BuildThelen2003MuscleDeprecated(const ForceBuildInput& in) {
  const model::ElementValues& v = in.values;
  muscles::Thelen2003DeprecatedParameters p;
  p.muscle = muscles::ReadMuscleParameters(in.force.version, v);
  p.activation_time_constant = v.Double("activation_time_constant", p.activation_time_constant);
  p.deactivation_time_constant =
      v.Double("deactivation_time_constant", p.deactivation_time_constant);
  p.Vmax = v.Double("Vmax", p.Vmax);
  p.Vmax0 = v.Double("Vmax0", p.Vmax0);
  p.FmaxTendonStrain = v.Double("FmaxTendonStrain", p.FmaxTendonStrain);
  p.FmaxMuscleStrain = v.Double("FmaxMuscleStrain", p.FmaxMuscleStrain);
  p.KshapeActive = v.Double("KshapeActive", p.KshapeActive);
  p.KshapePassive = v.Double("KshapePassive", p.KshapePassive);
  p.damping = v.Double("damping", p.damping);
  p.Af = v.Double("Af", p.Af);
  p.Flen = v.Double("Flen", p.Flen);
  // OpenSim 2.x muscles start at activation 0 and fiber length 0 unless states are given.
  p.default_activation = 0.0;
  p.default_fiber_length = 0.0;
  std::shared_ptr<const muscles::Thelen2003MuscleDeprecated> model;
  try {
    model = std::make_shared<muscles::Thelen2003MuscleDeprecated>(p);
  } catch (const Error& error) {
    v.Fail(error.message());
  }
  return MakePathActuator(in, v.Double("optimal_force", 1.0), std::move(model), 0.0, 1.0);
}

// Schutte1993Muscle(_Deprecated) and RigidTendonMuscle: ReadSchutte1993Muscle /
// ReadRigidTendonMuscle name the file, the line and the muscle in their errors.
std::shared_ptr<engine::ForceElement> BuildSchutte1993Muscle(const ForceBuildInput& in) {
  return MakePathActuator(in, in.values.Double("optimal_force", 1.0),
                          std::make_shared<muscles::Schutte1993Muscle>(
                              muscles::ReadSchutte1993Muscle(in.spec, in.force)),
                          0.0, 1.0);
}

std::shared_ptr<engine::ForceElement> BuildRigidTendonMuscle(const ForceBuildInput& in) {
  return MakePathActuator(in, in.values.Double("optimal_force", 1.0),
                          std::make_shared<muscles::RigidTendonMuscle>(
                              muscles::ReadRigidTendonMuscle(in.spec, in.force)),
                          0.0, 1.0);
}

std::shared_ptr<engine::ForceElement> BuildMillard2012EquilibriumMuscle(const ForceBuildInput& in) {
  // ReadMillard2012Muscle names the file, the line and the muscle in its errors.
  const muscles::Millard2012Muscle muscle = muscles::ReadMillard2012Muscle(in.spec, in.force);
  if (in.notes) {
    for (const std::string& adjustment : muscle.adjustments()) {
      in.notes->push_back({in.force.where, in.force.path, adjustment});
    }
  }
  const muscles::Millard2012Parameters& p = muscle.parameters();
  const double min_control = p.min_control.value_or(p.minimum_activation);
  return MakePathActuator(in, in.values.Double("optimal_force", 1.0),
                          std::make_shared<muscles::Millard2012Tension>(muscle), min_control, 1.0);
}

std::shared_ptr<engine::ForceElement> BuildDeGrooteFregly2016Muscle(const ForceBuildInput& in) {
  std::shared_ptr<const muscles::DeGrooteFregly2016Tension> model;
  try {
    model = std::make_shared<muscles::DeGrooteFregly2016Tension>(
        muscles::ReadDeGrooteFregly2016Muscle(in.spec, in.force));
  } catch (const Error& error) {
    if (!error.where().file.empty()) throw;
    in.values.Fail(error.message());
  }
  return MakePathActuator(in, 1.0, std::move(model), 0.0, 1.0);
}

}  // namespace sinew::opensim::internal

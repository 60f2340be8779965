#include <sinew/common/error.h>
#include <sinew/model/element_values.h>
#include <sinew/model/force_source.h>
#include <sinew/muscles/internal/muscle_base_properties.h>
#include <sinew/muscles/millard2012_spec.h>

namespace sinew::muscles {

namespace {

// A number property that may be written empty for "not set" (OpenSim's optional properties).
std::optional<double> Optional(const model::ElementValues& values, const model::Element& element,
                               const char* tag) {
  const model::Element* child = element.Child(tag);
  if (child == nullptr || child->text.empty()) return std::nullopt;
  return values.Double(tag, 0.0);
}

// Reads the curve element `tag` of the muscle, when present, with `read` on its values.
template <typename Read>
void ReadCurve(const model::ForceSpec& force, const std::string& file, const char* tag, Read read) {
  const model::Element* curve = force.element.Child(tag);
  if (curve == nullptr) return;
  read(model::ElementValues(*curve, file, force.path + "/" + tag), *curve);
}

}  // namespace

Millard2012Parameters ReadMillard2012Parameters(const model::ModelSpec& spec,
                                                const model::ForceSpec& force) {
  const std::string& file = model::SourceFile(spec, force);
  const model::ElementValues v(force.element, file, force.path);
  Millard2012Parameters p;
  p.name = force.path;
  internal::ReadMuscleBaseProperties(v, &p);
  p.fiber_damping = v.Double("fiber_damping", p.fiber_damping);
  p.default_activation = v.Double("default_activation", p.default_activation);
  p.default_fiber_length = Optional(v, force.element, "default_fiber_length");
  p.activation_time_constant = v.Double("activation_time_constant", p.activation_time_constant);
  p.deactivation_time_constant =
      v.Double("deactivation_time_constant", p.deactivation_time_constant);
  p.minimum_activation = v.Double("minimum_activation", p.minimum_activation);
  if (v.Has("min_control")) p.min_control = v.Bound("min_control", 0.0);
  if (force.version < 30513 && p.min_control == 0.0) p.min_control.reset();
  p.maximum_pennation_angle = v.Double("maximum_pennation_angle", p.maximum_pennation_angle);

  ReadCurve(force, file, "ActiveForceLengthCurve",
            [&](const model::ElementValues& c, const model::Element&) {
              ActiveForceLengthCurveParameters& a = p.active_force_length;
              a.min_norm_active_fiber_length =
                  c.Double("min_norm_active_fiber_length", a.min_norm_active_fiber_length);
              a.transition_norm_fiber_length =
                  c.Double("transition_norm_fiber_length", a.transition_norm_fiber_length);
              a.max_norm_active_fiber_length =
                  c.Double("max_norm_active_fiber_length", a.max_norm_active_fiber_length);
              a.shallow_ascending_slope =
                  c.Double("shallow_ascending_slope", a.shallow_ascending_slope);
              a.minimum_value = c.Double("minimum_value", a.minimum_value);
            });
  ReadCurve(
      force, file, "ForceVelocityCurve", [&](const model::ElementValues& c, const model::Element&) {
        ForceVelocityCurveParameters& f = p.force_velocity;
        f.concentric_slope_at_vmax =
            c.Double("concentric_slope_at_vmax", f.concentric_slope_at_vmax);
        f.concentric_slope_near_vmax =
            c.Double("concentric_slope_near_vmax", f.concentric_slope_near_vmax);
        f.isometric_slope = c.Double("isometric_slope", f.isometric_slope);
        f.eccentric_slope_at_vmax = c.Double("eccentric_slope_at_vmax", f.eccentric_slope_at_vmax);
        f.eccentric_slope_near_vmax =
            c.Double("eccentric_slope_near_vmax", f.eccentric_slope_near_vmax);
        f.max_eccentric_velocity_force_multiplier = c.Double(
            "max_eccentric_velocity_force_multiplier", f.max_eccentric_velocity_force_multiplier);
        f.concentric_curviness = c.Double("concentric_curviness", f.concentric_curviness);
        f.eccentric_curviness = c.Double("eccentric_curviness", f.eccentric_curviness);
      });
  ReadCurve(force, file, "FiberForceLengthCurve",
            [&](const model::ElementValues& c, const model::Element& e) {
              FiberForceLengthCurveParameters& f = p.fiber_force_length;
              f.strain_at_zero_force = c.Double("strain_at_zero_force", f.strain_at_zero_force);
              f.strain_at_one_norm_force =
                  c.Double("strain_at_one_norm_force", f.strain_at_one_norm_force);
              f.stiffness_at_low_force = Optional(c, e, "stiffness_at_low_force");
              f.stiffness_at_one_norm_force = Optional(c, e, "stiffness_at_one_norm_force");
              f.curviness = Optional(c, e, "curviness");
            });
  ReadCurve(force, file, "TendonForceLengthCurve",
            [&](const model::ElementValues& c, const model::Element& e) {
              TendonForceLengthCurveParameters& t = p.tendon_force_length;
              t.strain_at_one_norm_force =
                  c.Double("strain_at_one_norm_force", t.strain_at_one_norm_force);
              t.stiffness_at_one_norm_force = Optional(c, e, "stiffness_at_one_norm_force");
              t.norm_force_at_toe_end = Optional(c, e, "norm_force_at_toe_end");
              t.curviness = Optional(c, e, "curviness");
            });
  return p;
}

Millard2012Muscle ReadMillard2012Muscle(const model::ModelSpec& spec,
                                        const model::ForceSpec& force) {
  const Millard2012Parameters parameters = ReadMillard2012Parameters(spec, force);
  try {
    return Millard2012Muscle(parameters);
  } catch (const Error& error) {
    throw Error(SourceLocation{model::SourceFile(spec, force), force.element.line}, force.path,
                error.message());
  }
}

}  // namespace sinew::muscles

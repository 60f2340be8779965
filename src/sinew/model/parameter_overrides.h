// Per-run changes of a model's properties ("parameters"), applied to a parsed spec before a
// System is built from it: a parameter sweep's masses, stiffnesses, muscle strengths, ...
#pragma once

#include <sinew/model/model_spec.h>

#include <string>
#include <vector>

namespace sinew::model {

/// One override: `key` is "<component>/<property>", the component named by its name
/// ("BIClong") or by its path ("/forceset/BIClong"), the property as the file writes it
/// ("max_isometric_force"); `values` its new value, one number for a scalar property, as many
/// as the file writes for a vector one (3 for mass_center, 6 for inertia).
struct ParameterOverride {
  std::string key;
  std::vector<double> values;
};

/// Applies `overrides` to `spec` in order, so that the builders then read the new values.
/// What can be overridden (see docs/python.md, "Parameter overrides"):
/// - a body's `mass` (kg, >= 0), `mass_center` (p_BCm, 3 numbers, m), `inertia` (about the
///   mass centre in body axes, [Ixx Iyy Izz Ixy Ixz Iyz], kg m^2, moments >= 0) and the 3.x
///   `inertia_xx` ... `inertia_yz`;
/// - a coordinate's `default_value`, `default_speed_value` and `range` (2 numbers, min <= max);
/// - a force's (actuator's, muscle's) numeric properties written directly in its element in the
///   file (`max_isometric_force`, `stiffness`, `optimal_force`, ...), with as many numbers as
///   the file writes; not the frame offsets the reader resolves (location_body_1, ...).
/// Joints, frames, path points, constraints, markers, controllers and contact geometry cannot
/// be overridden yet. Throws sinew::Error (file `spec.file`, the property's or the component's
/// line, the component's path) for an unknown or ambiguous component (with close names), a
/// property it does not have or that cannot be overridden, the wrong number of values, NaN, or
/// a value the property cannot take.
void ApplyParameterOverrides(ModelSpec& spec, const std::vector<ParameterOverride>& overrides);

}  // namespace sinew::model

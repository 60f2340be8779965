// Spec -> engine: the skeleton of an OpenSim model (bodies, joints, coordinates, gravity) as an
// engine::System. The full OpenSim parser (forces, constraints, its Report) builds on this.
#pragma once

#include <sinew/common/error.h>
#include <sinew/engine/system.h>
#include <sinew/model/model_spec.h>

#include <memory>
#include <vector>

namespace sinew::opensim {

/// Choices made when building a System from a spec.
struct BuildOptions {
  /// Impose PinJoint, BallJoint, UniversalJoint and WeldJoint with their direct Cartesian
  /// constraints (no joint unknowns); otherwise every joint uses the exact coordinate-
  /// parameterized form. Joints with locked or prescribed coordinates, or with coordinates a
  /// simulated constraint uses (a CoordinateCouplerConstraint), always use the latter.
  bool direct_joints = true;
};

/// Where each spec element went in an engine::System (spec index -> engine index).
struct SpecToSystem {
  std::vector<int> bodies;       ///< per spec body (0, ground, maps to engine ground 0)
  std::vector<int> joints;       ///< per spec joint
  std::vector<int> coordinates;  ///< per spec coordinate (kNone for one no joint uses)
};

/// Adds `spec`'s skeleton (bodies, joints, coordinates) to `system`, which must not be
/// finalized; bodies, joints and coordinates are appended after what `system` already holds,
/// the spec's ground being the system's ground. Gravity, forces and constraints are left to the
/// caller. Throws sinew::Error (file, line, component) for a skeleton that cannot be built.
SpecToSystem BuildInto(const model::ModelSpec& spec, engine::System& system,
                       const BuildOptions& options, Diagnostics* notes);

/// Builds the engine system of `spec`'s skeleton: engine body i is spec body i (0 = ground),
/// engine joint j is spec joint j, engine coordinate c is spec coordinate c (same names).
/// Coordinates start at default_value / default_speed_value; locked ones stay at their
/// default value, prescribed ones follow prescribed_function. Forces, constraints, contact
/// and controllers are not built here: each is listed in `notes` (when not null).
/// Throws sinew::Error (file, line, component) for a model that cannot be simulated.
std::unique_ptr<engine::System> BuildSystem(const model::ModelSpec& spec,
                                            const BuildOptions& options = {},
                                            Diagnostics* notes = nullptr);

}  // namespace sinew::opensim

// The constraint forces table of a simulation (`sinew simulate --report-constraint-forces`):
// the loads of the model's constraints (its ConstraintSet) with OpenSim's record labels and
// sign, as OpenSim's ForceReporter writes them with include_constraint_forces.
#pragma once

#include <sinew/engine/dynamics.h>
#include <sinew/engine/loads.h>
#include <sinew/engine/state.h>
#include <sinew/engine/system.h>

#include <string>
#include <vector>

namespace sinew::opensim {

/// For every extra constraint of `system` (the model's constraints, in file order), OpenSim's
/// Constraint::getRecordLabels: for each body it constrains (ground included)
/// `<constraint>_<body>_Fx`, `_Fy`, `_Fz`, `_Mx`, `_My`, `_Mz`, then for each coordinate it
/// constrains `<constraint>_mobility_F<i>` (i from 0, in the constraint's coordinate order).
std::vector<std::string> ConstraintForcesLabels(const engine::System& system);

/// The values in ConstraintForcesLabels order at `state` (computes the accelerations with the
/// applied loads of CalcLoads plus `external`, which may be null): forces (N) and moments about
/// the body's origin (N m), expressed in ground, and generalized forces (N m or N). As in
/// OpenSim (Simbody's calcConstraintForcesFromMultipliers) they are the OPPOSITE of the loads
/// the constraint applies: a body welded to ground and hanging under gravity g reports
/// F = m g on itself (pointing down) and -m g on ground.
void ConstraintForcesRow(const engine::System& system, const engine::State& state,
                         const engine::Loads* external, engine::Data& data,
                         std::vector<double>& row);

}  // namespace sinew::opensim

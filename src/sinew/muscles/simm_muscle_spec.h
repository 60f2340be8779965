// The spline-based muscles from the model spec (Schutte1993Muscle_Deprecated / Schutte1993Muscle,
// RigidTendonMuscle) and the properties every Muscle shares, as OpenSim reads them.
#pragma once

#include <sinew/model/element_values.h>
#include <sinew/model/model_spec.h>
#include <sinew/muscles/rigid_tendon_muscle.h>
#include <sinew/muscles/schutte1993_muscle.h>

namespace sinew::muscles {

/// max_isometric_force, optimal_fiber_length, tendon_slack_length, pennation_angle_at_optimal
/// (`pennation_angle` in files of format 20301 and older, which OpenSim renames) and
/// max_contraction_velocity, with OpenSim's defaults; `version` is the format version of the
/// document the muscle was read from (ForceSpec::version).
MuscleParameters ReadMuscleParameters(int version, const model::ElementValues& v);

/// The Schutte1993Muscle(_Deprecated) `force` of `spec`, its curves from the file or OpenSim's
/// defaults. Throws sinew::Error naming the file, the line and the force for values OpenSim
/// refuses (either ignore flag set) or that would divide by zero.
Schutte1993Muscle ReadSchutte1993Muscle(const model::ModelSpec& spec,
                                        const model::ForceSpec& force);

/// The RigidTendonMuscle `force` of `spec`; errors as above.
RigidTendonMuscle ReadRigidTendonMuscle(const model::ModelSpec& spec,
                                        const model::ForceSpec& force);

}  // namespace sinew::muscles

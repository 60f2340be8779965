// The default curves of OpenSim's spline-based muscles (Schutte1993Muscle_Deprecated and
// RigidTendonMuscle): the knots their constructors give a curve property that a file leaves
// out. Normalized: fiber lengths per optimal fiber length, tendon strain, fiber velocity per
// maximum contraction velocity, forces per maximum isometric force.
#pragma once

#include <sinew/functions/function.h>

namespace sinew::muscles {

/// Active force-length multiplier against normalized fiber length (21 knots; both models).
functions::FunctionPtr MakeDefaultActiveForceLengthCurve();
/// Passive force-length multiplier against normalized fiber length (13 knots; RigidTendonMuscle's
/// default; a Schutte muscle without the property uses an exponential instead).
functions::FunctionPtr MakeDefaultPassiveForceLengthCurve();
/// Schutte's tendon force against tendon strain (17 knots).
functions::FunctionPtr MakeDefaultTendonForceLengthCurve();
/// RigidTendonMuscle's force-velocity multiplier against normalized fiber velocity, lengthening
/// positive (42 knots: 0 at -1, 1 at 0, 1.77 at 1).
functions::FunctionPtr MakeDefaultForceVelocityCurve();

}  // namespace sinew::muscles

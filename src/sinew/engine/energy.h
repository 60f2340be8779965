// Mechanical energy of a state: kinetic energy of every body (about its mass centre), the
// potential energy of uniform gravity (zero at the ground origin) and that stored in force
// elements (springs); and the power of applied loads, for energy balances with dissipation.
#pragma once

#include <sinew/engine/state.h>
#include <sinew/engine/system.h>

namespace sinew::engine {

/// Sum over bodies of 1/2 m |v_Cm|^2 + 1/2 w^T I_Cm w (J).
double CalcKineticEnergy(const System& system, const State& state);
/// Sum over bodies of -m g . p_GCm (J).
double CalcGravityPotentialEnergy(const System& system, const State& state);
/// Sum of the force elements' potential energies (ForceElement::CalcPotentialEnergy, J).
double CalcForcePotentialEnergy(const System& system, const State& state);
/// Kinetic, gravity potential and force potential energy (J). Without non-conservative loads it
/// is constant along a motion.
double CalcMechanicalEnergy(const System& system, const State& state);

/// The power (W) that force element k's loads deliver to the bodies and coordinates at
/// `state`: sum of torque . w + force . v_Bo over bodies and of generalized force . u over
/// coordinates. For a conservative element it equals -dV/dt; in general d/dt of
/// CalcMechanicalEnergy is the sum over elements of (power + dV_k/dt).
double CalcForcePower(const System& system, const State& state, int k);

}  // namespace sinew::engine

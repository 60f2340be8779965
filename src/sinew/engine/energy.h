// Mechanical energy of a state: kinetic energy of every body (about its mass centre) and the
// potential energy of uniform gravity (zero at the ground origin).
#pragma once

#include <sinew/engine/state.h>
#include <sinew/engine/system.h>

namespace sinew::engine {

/// Sum over bodies of 1/2 m |v_Cm|^2 + 1/2 w^T I_Cm w (J).
double CalcKineticEnergy(const System& system, const State& state);
/// Sum over bodies of -m g . p_GCm (J).
double CalcGravityPotentialEnergy(const System& system, const State& state);
/// Kinetic plus gravity potential energy (J); force elements' potentials are not included.
double CalcMechanicalEnergy(const System& system, const State& state);

}  // namespace sinew::engine

// Millard2012EquilibriumMuscle's mathematics as pure functions of (muscle, inputs): the fiber
// and tendon kinematics, the fiber velocity (inverse force-velocity curve, or the damped
// equilibrium solved by Newton's method), the forces, fiber-tendon equilibrium at a path length
// and speed, and first-order activation dynamics. Lengths in m, speeds in m/s, forces in N.
#pragma once

#include <sinew/muscles/millard2012_parameters.h>

namespace sinew::muscles {

/// Everything OpenSim's MuscleLengthInfo, FiberVelocityInfo and MuscleDynamicsInfo hold for a
/// Millard2012EquilibriumMuscle at one instant.
struct Millard2012Dynamics {
  // Lengths.
  double fiber_length = 0.0;  ///< clamped to the minimum fiber length
  double norm_fiber_length = 0.0;
  double pennation_angle = 0.0;  ///< rad
  double cos_pennation = 1.0;
  double sin_pennation = 0.0;
  double fiber_length_along_tendon = 0.0;
  double tendon_length = 0.0;
  double norm_tendon_length = 0.0;               ///< tendon length / slack length
  double active_force_length_multiplier = 0.0;   ///< fal(l~)
  double passive_force_length_multiplier = 0.0;  ///< fpe(l~)
  // Velocities.
  double fiber_velocity = 0.0;       ///< d(fiber_length)/dt, the fiber_length state's derivative
  double norm_fiber_velocity = 0.0;  ///< fiber velocity / (vmax optimal length)
  double fiber_velocity_along_tendon = 0.0;
  double pennation_angular_velocity = 0.0;
  double tendon_velocity = 0.0;
  double force_velocity_multiplier = 1.0;  ///< fv(v~)
  /// True when the fiber is at its minimum length and not lengthening: velocity and forces are
  /// then 0 and the tendon takes the whole path speed.
  bool fiber_state_clamped = false;
  // Forces.
  double activation = 0.0;                   ///< clamped to [minimum_activation, 1]
  double active_fiber_force = 0.0;           ///< Fiso a fal fv
  double passive_elastic_fiber_force = 0.0;  ///< Fiso fpe
  double passive_damping_fiber_force = 0.0;  ///< Fiso beta v~
  double passive_fiber_force = 0.0;          ///< elastic + damping
  double fiber_force = 0.0;                  ///< active + passive
  double fiber_force_along_tendon = 0.0;     ///< fiber_force cos(phi)
  double tendon_force = 0.0;                 ///< Fiso fse(l~T) (rigid tendon: fiber force along it)
  double norm_tendon_force = 0.0;
  double fiber_stiffness = 0.0;               ///< dFm/dlce, N/m
  double fiber_stiffness_along_tendon = 0.0;  ///< d(Fm cos phi)/d(lce cos phi)
  double tendon_stiffness = 0.0;              ///< dFt/dlt (infinite for a rigid tendon)
};

/// The muscle's state of length, velocity and force. `activation` is the activation state (or
/// the excitation when activation dynamics are ignored; clamped here), `fiber_length` the
/// fiber_length state (unused with a rigid tendon, where the fiber takes the path length less
/// the slack length). Throws sinew::Error naming the muscle where OpenSim throws: an undamped
/// compliant fiber at 90 degrees pennation, zero activation or zero active force-length, and a
/// damped fiber velocity whose Newton iteration does not converge.
Millard2012Dynamics CalcMillard2012Dynamics(const Millard2012Muscle& muscle, double activation,
                                            double fiber_length, double path_length,
                                            double path_lengthening_speed);

/// The elastic energy stored in the fiber's passive element and in the tendon (J), as OpenSim's
/// calcMusclePotentialEnergyInfo defines it: optimal length Fiso times the passive curve's
/// integral from its start to l~, and slack length Fiso times the tendon curve's integral
/// (0 with a rigid tendon). Their derivatives with respect to the fiber and tendon lengths are
/// the passive elastic fiber force and the tendon force.
struct Millard2012PotentialEnergy {
  double fiber = 0.0;
  double tendon = 0.0;
};
Millard2012PotentialEnergy CalcMillard2012PotentialEnergy(const Millard2012Muscle& muscle,
                                                          const Millard2012Dynamics& dynamics);

/// Millard's first-order activation dynamics, da/dt = (u - a) / tau with
/// tau = activation_time_constant (0.5 + 1.5 a) when u > a, deactivation_time_constant /
/// (0.5 + 1.5 a) otherwise, a clamped to [minimum_activation, 1] first.
double CalcMillard2012ActivationDerivative(const Millard2012Muscle& muscle, double activation,
                                           double excitation);

/// The fiber length at which fiber and tendon carry the same force.
struct Millard2012Equilibrium {
  enum class Status {
    kConverged,         ///< |fiber force along tendon - tendon force| below the tolerance
    kFiberAtLowerBound  ///< no equilibrium above the minimum fiber length: fiber left there
  };
  Status status = Status::kConverged;
  double fiber_length = 0.0;    ///< m, clamped to the minimum
  double tendon_force = 0.0;    ///< N
  double solution_error = 0.0;  ///< N, fiber force along tendon - tendon force
  int iterations = 0;
};

/// OpenSim's computeFiberEquilibrium (estimateMuscleFiberState): Newton's method with step
/// halving on fiber force along the tendon - tendon force, from a tendon at 1.01 slack lengths,
/// tolerance max(1e-8 Fiso, 10 SignificantReal), at most 200 iterations. A nonzero
/// `path_lengthening_speed` shares it between fiber and tendon by their stiffnesses (OpenSim's
/// solveForVelocity; equilibrateMuscles passes 0). With a rigid tendon there is nothing to
/// solve: the fiber length follows the path. Throws sinew::Error naming the muscle when the
/// iterations run out.
Millard2012Equilibrium SolveMillard2012Equilibrium(const Millard2012Muscle& muscle,
                                                   double activation, double path_length,
                                                   double path_lengthening_speed);

}  // namespace sinew::muscles

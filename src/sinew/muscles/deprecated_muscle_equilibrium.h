// OpenSim's muscle-tendon equilibrium for its deprecated muscles (computeIsometricForce of
// Schutte1993Muscle_Deprecated and Thelen2003Muscle_Deprecated: one iteration, the curves
// differ). docs/muscles.md#initial-fiber-lengths-and-equilibrium.
#pragma once

#include <sinew/muscles/tension_model.h>
#include <sinew/muscles/thelen2003_muscle.h>

#include <functional>
#include <string>

namespace sinew::muscles {

/// The normalized curves the iteration reads, and the pennation of a fiber.
struct DeprecatedMuscleCurves {
  /// Tendon force / Fiso at a tendon strain, in the force balance.
  std::function<double(double)> tendon_force;
  /// Tendon force / Fiso at a tendon strain, in the tendon stiffness estimate (Schutte's
  /// OpenSim reads its spline there without the balance's zero below slack).
  std::function<double(double)> tendon_force_in_stiffness;
  /// Active force-length multiplier at fiber length / optimal (not clamped).
  std::function<double(double)> active_force_length;
  /// Passive fiber force / Fiso at fiber length / optimal (not clamped).
  std::function<double(double)> passive_force_length;
  /// Pennation angle (rad) of a fiber of length (m).
  std::function<double(double)> pennation;
};

/// OpenSim's computeIsometricForce: from the optimal fiber length, steps of
/// error / (fiber stiffness / cos + tendon stiffness) (each at most half an optimal length,
/// the stiffnesses OpenSim's rough estimates), and a secant step whenever the error changes
/// sign, the tendon never shorter than its slack length, until tendon force and fiber force
/// along the tendon (active and passive parts not below 0, fiber velocity 0) agree to 0.01 N.
/// The fiber length (m) it ends at, and how:
/// - kBalanced: within 0.01 N; for a path shorter than the tendon's slack length, the muscle's
///   width (OpenSim's answer: no force);
/// - kTendonAtSlackLength: the 100 iterations ended with the tendon held at its slack length
///   and the forces further apart (a fiber that cannot balance even a slack tendon's pull, or
///   a balance only a tendon shorter than slack would give); OpenSim keeps that fiber length.
/// Throws sinew::Error naming `component` when the activation or path length is not finite or
/// the iterations end further apart with the tendon longer than slack.
struct DeprecatedEquilibrium {
  double fiber_length = 0.0;
  EquilibriumStatus status = EquilibriumStatus::kBalanced;
};
DeprecatedEquilibrium SolveDeprecatedIsometricFiberLength(const MuscleParameters& muscle,
                                                          const DeprecatedMuscleCurves& curves,
                                                          double activation, double path_length,
                                                          const std::string& component);

/// Tendon force less fiber force along the tendon (N) at zero fiber velocity, as the iteration
/// measures it, for a fiber of length `fiber_length` in a path of length `path_length` (m).
double DeprecatedIsometricImbalance(const MuscleParameters& muscle,
                                    const DeprecatedMuscleCurves& curves, double activation,
                                    double fiber_length, double path_length);

}  // namespace sinew::muscles

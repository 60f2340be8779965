// The small interface a muscle model implements (and the ideal path actuator too): its state
// variables, the tension it pulls its path with from (excitation, its state variables, the
// path's length and lengthening speed), the derivatives of its state variables, and
// muscle-tendon equilibrium. A PathActuator element (path_actuator.h) runs any of them on an
// engine State; a new muscle class is one TensionModel and one registry entry.
#pragma once

#include <sinew/math/types.h>
#include <sinew/muscles/engine_path.h>

#include <string>
#include <vector>

namespace sinew::muscles {

/// What a model computes at one instant (SI units; NaN where a model has no such quantity).
struct MuscleQuantities {
  double activation = 0.0;           ///< as used for force (clamped into the model's range)
  double fiber_length = 0.0;         ///< m (clamped to the minimum fiber length)
  double fiber_velocity = 0.0;       ///< m/s, lengthening positive
  double pennation_angle = 0.0;      ///< rad
  double tendon_length = 0.0;        ///< m
  double active_fiber_force = 0.0;   ///< N, along the fiber
  double passive_fiber_force = 0.0;  ///< N, along the fiber
  double tendon_force = 0.0;         ///< N: the tension along the path
};

/// The MuscleQuantities of a model's dynamics result `d` (any struct with the same field names,
/// e.g. Millard2012Dynamics, DeGrooteFregly2016Dynamics).
template <class Dynamics>
MuscleQuantities QuantitiesOf(const Dynamics& d) {
  MuscleQuantities out;
  out.activation = d.activation;
  out.fiber_length = d.fiber_length;
  out.fiber_velocity = d.fiber_velocity;
  out.pennation_angle = d.pennation_angle;
  out.tendon_length = d.tendon_length;
  out.active_fiber_force = d.active_fiber_force;
  out.passive_fiber_force = d.passive_fiber_force;
  out.tendon_force = d.tendon_force;
  return out;
}

/// How an equilibrium was found.
enum class EquilibriumStatus {
  kBalanced,              ///< fiber force along the tendon = tendon force
  kFiberAtMinimumLength,  ///< even the shortest fiber pulls harder: fiber at its minimum
  /// OpenSim's iteration for its deprecated muscles ended with the tendon held at its slack
  /// length (it never shortens it further) and the forces still apart: the fiber takes the
  /// rest of the path, as in OpenSim
  kTendonAtSlackLength,
};

/// A model of the tension along a path. Immutable; its changing values live in the engine
/// State (z: StateVariableNames(); one input, the excitation).
class TensionModel {
 public:
  virtual ~TensionModel() = default;

  /// Names of the state variables ("activation", "fiber_length", ...); none by default.
  virtual std::vector<std::string> StateVariableNames() const { return {}; }
  /// Their values before any initialization (the file's defaults).
  virtual void SetDefaultStateVariables(Eigen::Ref<VecX> z) const { (void)z; }

  /// Everything the model computes at state variables `z`, excitation `excitation` and the
  /// path's length and speed. Its tendon_force is the tension applied to the path.
  virtual MuscleQuantities Calc(Eigen::Ref<const VecX> z, double excitation,
                                const PathKinematics& path) const = 0;
  /// dz/dt at the same arguments, given what Calc returned for them.
  virtual void CalcStateVariableDerivatives(Eigen::Ref<const VecX> z, double excitation,
                                            const PathKinematics& path,
                                            const MuscleQuantities& quantities,
                                            Eigen::Ref<VecX> zdot) const {
    (void)z, (void)excitation, (void)path, (void)quantities;
    zdot.setZero();
  }
  /// Sets the fiber state in `z` so that the fiber and tendon forces balance at the
  /// activation `z` holds and the path's length and speed (OpenSim's
  /// computeInitialFiberEquilibrium). Throws sinew::Error naming `component` when there is no
  /// equilibrium. Default: nothing to solve.
  virtual EquilibriumStatus Equilibrate(const PathKinematics& path, const std::string& component,
                                        Eigen::Ref<VecX> z) const {
    (void)path, (void)component, (void)z;
    return EquilibriumStatus::kBalanced;
  }
};

}  // namespace sinew::muscles

// OpenSim's Millard2012EquilibriumMuscle as a TensionModel: the pure functions of
// millard2012_equilibrium.h (curves, damped or classic fiber velocity, forces, equilibrium,
// activation dynamics) on a PathActuator's state variables. State variables: "activation"
// (unless ignore_activation_dynamics: the excitation is then the activation) and
// "fiber_length" (unless ignore_tendon_compliance: the fiber then follows the path).
#pragma once

#include <sinew/muscles/millard2012_parameters.h>
#include <sinew/muscles/muscle_state_layout.h>
#include <sinew/muscles/tension_model.h>

namespace sinew::muscles {

/// A Millard2012EquilibriumMuscle on a path.
class Millard2012Tension final : public TensionModel {
 public:
  explicit Millard2012Tension(Millard2012Muscle muscle);

  const Millard2012Muscle& muscle() const { return muscle_; }

  std::vector<std::string> StateVariableNames() const override;
  /// default_activation and default_fiber_length (the optimal fiber length when absent).
  void SetDefaultStateVariables(Eigen::Ref<VecX> z) const override;
  MuscleQuantities Calc(Eigen::Ref<const VecX> z, double excitation,
                        const PathKinematics& path) const override;
  void CalcStateVariableDerivatives(Eigen::Ref<const VecX> z, double excitation,
                                    const PathKinematics& path, const MuscleQuantities& quantities,
                                    Eigen::Ref<VecX> zdot) const override;
  /// SolveMillard2012Equilibrium at the activation z holds (default_activation when activation
  /// dynamics are ignored: the excitation is not known here) and the path's length and speed.
  /// Nothing to solve with a rigid tendon. Throws sinew::Error naming `component` when
  /// OpenSim's iterations do not converge.
  EquilibriumStatus Equilibrate(const PathKinematics& path, const std::string& component,
                                Eigen::Ref<VecX> z) const override;

 private:
  Millard2012Muscle muscle_;
  MuscleStateLayout layout_;
};

}  // namespace sinew::muscles

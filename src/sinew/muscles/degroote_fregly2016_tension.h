// OpenSim's DeGrooteFregly2016Muscle as a TensionModel: the pure functions of
// degroote_fregly2016_muscle.h in their explicit form on a PathActuator's state variables.
// State variables: "activation" (unless ignore_activation_dynamics: the excitation is then the
// activation) and "normalized_tendon_force" (unless ignore_tendon_compliance).
#pragma once

#include <sinew/muscles/degroote_fregly2016_muscle.h>
#include <sinew/muscles/muscle_state_layout.h>
#include <sinew/muscles/tension_model.h>

namespace sinew::muscles {

/// A DeGrooteFregly2016Muscle on a path (explicit tendon compliance dynamics).
class DeGrooteFregly2016Tension final : public TensionModel {
 public:
  /// Throws sinew::Error for the implicit tendon compliance mode (a forward simulation has no
  /// tendon force derivative to give it).
  explicit DeGrooteFregly2016Tension(DeGrooteFregly2016Muscle muscle);

  std::vector<std::string> StateVariableNames() const override;
  /// default_activation and default_normalized_tendon_force.
  void SetDefaultStateVariables(Eigen::Ref<VecX> z) const override;
  MuscleQuantities Calc(Eigen::Ref<const VecX> z, double excitation,
                        const PathKinematics& path) const override;
  void CalcStateVariableDerivatives(Eigen::Ref<const VecX> z, double excitation,
                                    const PathKinematics& path, const MuscleQuantities& quantities,
                                    Eigen::Ref<VecX> zdot) const override;
  /// SolveDeGrooteFregly2016Equilibrium at the activation z holds (default_activation when
  /// activation dynamics are ignored) and the path's length and speed; an error names
  /// `component` when there is none in [0, 5].
  EquilibriumStatus Equilibrate(const PathKinematics& path, const std::string& component,
                                Eigen::Ref<VecX> z) const override;

 private:
  DeGrooteFregly2016Dynamics Dynamics(Eigen::Ref<const VecX> z, double excitation,
                                      const PathKinematics& path) const;

  DeGrooteFregly2016Muscle muscle_;
  MuscleStateLayout layout_;
};

}  // namespace sinew::muscles

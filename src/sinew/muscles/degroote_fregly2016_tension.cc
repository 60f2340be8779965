#include <sinew/common/error.h>
#include <sinew/muscles/degroote_fregly2016_tension.h>

#include <utility>

namespace sinew::muscles {

DeGrooteFregly2016Tension::DeGrooteFregly2016Tension(DeGrooteFregly2016Muscle muscle)
    : muscle_(std::move(muscle)),
      layout_(muscle_.parameters().ignore_activation_dynamics,
              muscle_.parameters().ignore_tendon_compliance) {
  if (!muscle_.explicit_tendon_dynamics() && !muscle_.parameters().ignore_tendon_compliance) {
    throw Error("tendon_compliance_dynamics_mode 'implicit' needs the tendon force derivative "
                "a direct collocation solver gives; a forward simulation uses 'explicit'");
  }
}

std::vector<std::string> DeGrooteFregly2016Tension::StateVariableNames() const {
  return layout_.Names("normalized_tendon_force");
}

void DeGrooteFregly2016Tension::SetDefaultStateVariables(Eigen::Ref<VecX> z) const {
  const DeGrooteFregly2016Parameters& p = muscle_.parameters();
  if (layout_.activation >= 0) z[layout_.activation] = p.default_activation;
  if (layout_.fiber >= 0) z[layout_.fiber] = p.default_normalized_tendon_force;
}

DeGrooteFregly2016Dynamics DeGrooteFregly2016Tension::Dynamics(Eigen::Ref<const VecX> z,
                                                               double excitation,
                                                               const PathKinematics& path) const {
  return CalcDeGrooteFregly2016Dynamics(muscle_, layout_.Activation(z, excitation),
                                        layout_.Fiber(z, 0.0), path.length,
                                        path.lengthening_speed);
}

MuscleQuantities DeGrooteFregly2016Tension::Calc(Eigen::Ref<const VecX> z, double excitation,
                                                 const PathKinematics& path) const {
  const DeGrooteFregly2016Dynamics d = Dynamics(z, excitation, path);
  return QuantitiesOf(d);
}

void DeGrooteFregly2016Tension::CalcStateVariableDerivatives(Eigen::Ref<const VecX> z,
                                                             double excitation,
                                                             const PathKinematics& path,
                                                             const MuscleQuantities& /*quantities*/,
                                                             Eigen::Ref<VecX> zdot) const {
  if (layout_.activation >= 0) {
    zdot[layout_.activation] =
        CalcDeGrooteFregly2016ActivationDerivative(muscle_, z[layout_.activation], excitation);
  }
  if (layout_.fiber >= 0) {
    zdot[layout_.fiber] = Dynamics(z, excitation, path).norm_tendon_force_derivative;
  }
}

EquilibriumStatus DeGrooteFregly2016Tension::Equilibrate(const PathKinematics& path,
                                                         const std::string& component,
                                                         Eigen::Ref<VecX> z) const {
  if (layout_.fiber < 0) return EquilibriumStatus::kBalanced;
  const double activation = layout_.Activation(z, muscle_.parameters().default_activation);
  try {
    z[layout_.fiber] =
        SolveDeGrooteFregly2016Equilibrium(muscle_, activation, path.length, path.lengthening_speed);
  } catch (const Error& error) {
    throw Error({}, component, error.message());
  }
  return EquilibriumStatus::kBalanced;
}

}  // namespace sinew::muscles

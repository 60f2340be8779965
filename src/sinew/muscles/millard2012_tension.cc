#include <sinew/common/error.h>
#include <sinew/muscles/millard2012_equilibrium.h>
#include <sinew/muscles/millard2012_tension.h>

#include <utility>

namespace sinew::muscles {

Millard2012Tension::Millard2012Tension(Millard2012Muscle muscle)
    : muscle_(std::move(muscle)),
      layout_(muscle_.parameters().ignore_activation_dynamics,
              muscle_.parameters().ignore_tendon_compliance) {}

std::vector<std::string> Millard2012Tension::StateVariableNames() const {
  return layout_.Names("fiber_length");
}

void Millard2012Tension::SetDefaultStateVariables(Eigen::Ref<VecX> z) const {
  const Millard2012Parameters& p = muscle_.parameters();
  if (layout_.activation >= 0) z[layout_.activation] = p.default_activation;
  if (layout_.fiber >= 0) {
    z[layout_.fiber] = p.default_fiber_length.value_or(p.optimal_fiber_length);
  }
}

MuscleQuantities Millard2012Tension::Calc(Eigen::Ref<const VecX> z, double excitation,
                                          const PathKinematics& path) const {
  const Millard2012Dynamics d =
      CalcMillard2012Dynamics(muscle_, layout_.Activation(z, excitation), layout_.Fiber(z, 0.0),
                              path.length, path.lengthening_speed);
  return QuantitiesOf(d);
}

void Millard2012Tension::CalcStateVariableDerivatives(Eigen::Ref<const VecX> z,
                                                      double excitation,
                                                      const PathKinematics& /*path*/,
                                                      const MuscleQuantities& quantities,
                                                      Eigen::Ref<VecX> zdot) const {
  if (layout_.activation >= 0) {
    zdot[layout_.activation] =
        CalcMillard2012ActivationDerivative(muscle_, z[layout_.activation], excitation);
  }
  if (layout_.fiber >= 0) zdot[layout_.fiber] = quantities.fiber_velocity;
}

EquilibriumStatus Millard2012Tension::Equilibrate(const PathKinematics& path,
                                                  const std::string& component,
                                                  Eigen::Ref<VecX> z) const {
  if (layout_.fiber < 0) return EquilibriumStatus::kBalanced;
  const double activation = layout_.Activation(z, muscle_.parameters().default_activation);
  Millard2012Equilibrium equilibrium;
  try {
    equilibrium =
        SolveMillard2012Equilibrium(muscle_, activation, path.length, path.lengthening_speed);
  } catch (const Error& error) {
    throw Error({}, component, error.message());
  }
  z[layout_.fiber] = equilibrium.fiber_length;
  return equilibrium.status == Millard2012Equilibrium::Status::kFiberAtLowerBound
             ? EquilibriumStatus::kFiberAtMinimumLength
             : EquilibriumStatus::kBalanced;
}

}  // namespace sinew::muscles

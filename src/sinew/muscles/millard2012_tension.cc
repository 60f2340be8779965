#include <sinew/common/error.h>
#include <sinew/muscles/millard2012_equilibrium.h>
#include <sinew/muscles/millard2012_tension.h>

#include <utility>

namespace sinew::muscles {

Millard2012Tension::Millard2012Tension(Millard2012Muscle muscle) : muscle_(std::move(muscle)) {
  int next = 0;
  if (!muscle_.parameters().ignore_activation_dynamics) activation_index_ = next++;
  if (!muscle_.parameters().ignore_tendon_compliance) fiber_length_index_ = next++;
}

std::vector<std::string> Millard2012Tension::StateVariableNames() const {
  std::vector<std::string> names;
  if (activation_index_ >= 0) names.push_back("activation");
  if (fiber_length_index_ >= 0) names.push_back("fiber_length");
  return names;
}

void Millard2012Tension::SetDefaultStateVariables(Eigen::Ref<VecX> z) const {
  const Millard2012Parameters& p = muscle_.parameters();
  if (activation_index_ >= 0) z[activation_index_] = p.default_activation;
  if (fiber_length_index_ >= 0) {
    z[fiber_length_index_] = p.default_fiber_length.value_or(p.optimal_fiber_length);
  }
}

double Millard2012Tension::Activation(Eigen::Ref<const VecX> z, double excitation) const {
  return activation_index_ >= 0 ? z[activation_index_] : excitation;
}

MuscleQuantities Millard2012Tension::Calc(Eigen::Ref<const VecX> z, double excitation,
                                          const PathKinematics& path) const {
  const double fiber_length = fiber_length_index_ >= 0 ? z[fiber_length_index_] : 0.0;
  const Millard2012Dynamics d = CalcMillard2012Dynamics(
      muscle_, Activation(z, excitation), fiber_length, path.length, path.lengthening_speed);
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

void Millard2012Tension::CalcStateVariableDerivatives(Eigen::Ref<const VecX> z,
                                                      double excitation,
                                                      const PathKinematics& /*path*/,
                                                      const MuscleQuantities& quantities,
                                                      Eigen::Ref<VecX> zdot) const {
  if (activation_index_ >= 0) {
    zdot[activation_index_] =
        CalcMillard2012ActivationDerivative(muscle_, z[activation_index_], excitation);
  }
  if (fiber_length_index_ >= 0) zdot[fiber_length_index_] = quantities.fiber_velocity;
}

EquilibriumStatus Millard2012Tension::Equilibrate(const PathKinematics& path,
                                                  const std::string& component,
                                                  Eigen::Ref<VecX> z) const {
  if (fiber_length_index_ < 0) return EquilibriumStatus::kBalanced;
  const double activation = activation_index_ >= 0 ? z[activation_index_]
                                                   : muscle_.parameters().default_activation;
  Millard2012Equilibrium equilibrium;
  try {
    equilibrium =
        SolveMillard2012Equilibrium(muscle_, activation, path.length, path.lengthening_speed);
  } catch (const Error& error) {
    throw Error({}, component, error.message());
  }
  z[fiber_length_index_] = equilibrium.fiber_length;
  return equilibrium.status == Millard2012Equilibrium::Status::kFiberAtLowerBound
             ? EquilibriumStatus::kFiberAtMinimumLength
             : EquilibriumStatus::kBalanced;
}

}  // namespace sinew::muscles

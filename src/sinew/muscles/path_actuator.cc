#include <sinew/engine/state.h>
#include <sinew/muscles/path_actuator.h>

#include <utility>

namespace sinew::muscles {

MuscleQuantities IdealPathTension::Calc(Eigen::Ref<const VecX> /*z*/, double excitation,
                                        const PathKinematics& /*path*/) const {
  MuscleQuantities quantities;
  quantities.tendon_force = optimal_force_ * excitation;
  return quantities;
}

PathActuator::PathActuator(std::string name, double optimal_force, EnginePath path,
                           std::shared_ptr<const TensionModel> model, bool equilibrate)
    : forces::Actuator(std::move(name), optimal_force),
      path_(std::move(path)),
      model_(std::move(model)),
      num_z_(static_cast<int>(model_->StateVariableNames().size())),
      equilibrate_(equilibrate) {}

std::vector<std::string> PathActuator::StateVariableNames() const {
  return model_->StateVariableNames();
}

void PathActuator::SetDefaultStateVariables(Eigen::Ref<VecX> z) const {
  model_->SetDefaultStateVariables(z);
}

Eigen::Map<const VecX> PathActuator::StateVariables(const engine::ForceContext& context) const {
  return Eigen::Map<const VecX>(context.state.z.data() + context.z_begin, num_z_);
}

PathKinematics PathActuator::CalcPathKinematics(const engine::ForceContext& context) const {
  return path_.Calc(context.state, EnginePath::Scratch());
}

MuscleQuantities PathActuator::CalcQuantities(const engine::ForceContext& context) const {
  return model_->Calc(StateVariables(context), context.input(0), CalcPathKinematics(context));
}

void PathActuator::InitializeStateVariables(const engine::ForceContext& context,
                                            Eigen::Ref<VecX> z) const {
  if (!equilibrate_ || num_z_ == 0) return;
  model_->Equilibrate(CalcPathKinematics(context), path_.path().component(), z);
}

void PathActuator::CalcStateVariableDerivatives(const engine::ForceContext& context,
                                                Eigen::Ref<VecX> zdot) const {
  if (num_z_ > 0) Evaluate(context, nullptr, &zdot);
}

void PathActuator::AddLoads(const engine::ForceContext& context, engine::Loads& loads) const {
  Evaluate(context, &loads, nullptr);
}

void PathActuator::AddLoadsAndStateVariableDerivatives(const engine::ForceContext& context,
                                                       engine::Loads& loads,
                                                       Eigen::Ref<VecX> zdot) const {
  Evaluate(context, &loads, num_z_ > 0 ? &zdot : nullptr);
}

void PathActuator::Evaluate(const engine::ForceContext& context, engine::Loads* loads,
                            Eigen::Ref<VecX>* zdot) const {
  PathScratch& scratch = EnginePath::Scratch();
  const PathKinematics kinematics = path_.Calc(context.state, scratch);
  const auto z = StateVariables(context);
  const double excitation = context.input(0);
  const MuscleQuantities quantities = model_->Calc(z, excitation, kinematics);
  if (zdot) model_->CalcStateVariableDerivatives(z, excitation, kinematics, quantities, *zdot);
  if (loads) path_.AddTensionLoads(context.state, quantities.tendon_force, scratch, *loads);
}

void PathActuator::CalcRecordValues(const engine::ForceContext& context,
                                    std::vector<double>& values) const {
  values.push_back(CalcQuantities(context).tendon_force);
}

}  // namespace sinew::muscles

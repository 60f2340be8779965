#include <sinew/engine/loads.h>
#include <sinew/engine/state.h>
#include <sinew/forces/spring_generalized_force.h>

#include <utility>

namespace sinew::forces {

SpringGeneralizedForce::SpringGeneralizedForce(std::string name, int coordinate, double stiffness,
                                               double rest_length, double viscosity)
    : name_(std::move(name)),
      coordinate_(coordinate),
      stiffness_(stiffness),
      rest_length_(rest_length),
      viscosity_(viscosity) {}

double SpringGeneralizedForce::CalcForce(const engine::ForceContext& context) const {
  const engine::State& s = context.state;
  return -stiffness_ * (s.q[coordinate_] - rest_length_) - viscosity_ * s.u[coordinate_];
}

void SpringGeneralizedForce::AddLoads(const engine::ForceContext& context,
                                      engine::Loads& loads) const {
  loads.AddGeneralizedForce(coordinate_, CalcForce(context));
}

std::vector<std::string> SpringGeneralizedForce::RecordLabels(
    const engine::System& /*system*/) const {
  return {name_ + "_Force"};
}

void SpringGeneralizedForce::CalcRecordValues(const engine::ForceContext& context,
                                              std::vector<double>& values) const {
  values.push_back(CalcForce(context));
}

std::optional<engine::ForceSupport> SpringGeneralizedForce::Support() const {
  return engine::ForceSupport{{}, {coordinate_}};
}

bool SpringGeneralizedForce::CalcLoadJacobians(const engine::ForceContext&, Eigen::Ref<MatX> K,
                                               Eigen::Ref<MatX> D) const {
  K(0, 0) = -stiffness_;
  D(0, 0) = -viscosity_;
  return true;
}

double SpringGeneralizedForce::CalcPotentialEnergy(const engine::ForceContext& context) const {
  const double stretch = context.state.q[coordinate_] - rest_length_;
  return 0.5 * stiffness_ * stretch * stretch;
}

}  // namespace sinew::forces

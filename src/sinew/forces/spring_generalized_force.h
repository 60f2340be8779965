// OpenSim's SpringGeneralizedForce: a linear spring and damper acting on one coordinate.
#pragma once

#include <sinew/engine/force_element.h>

#include <string>

namespace sinew::forces {

/// Generalized force f = -stiffness (q - rest_length) - viscosity u on `coordinate` (OpenSim's
/// computeForceMagnitude; N or N m for a coordinate in m or rad, stiffness in N/m or N m/rad,
/// viscosity in N s/m or N m s/rad: SI, no degree conversion). Potential energy
/// stiffness (q - rest_length)^2 / 2 (OpenSim reports none; Sinew counts it so the energy
/// balance closes). u must be qdot: use it on coordinates of parameterized joints whose speed is
/// a coordinate rate.
class SpringGeneralizedForce final : public engine::ForceElement {
 public:
  SpringGeneralizedForce(std::string name, int coordinate, double stiffness, double rest_length,
                         double viscosity);

  std::string name() const override { return name_; }
  /// The generalized force for the context's state.
  double CalcForce(const engine::ForceContext& context) const;
  void AddLoads(const engine::ForceContext& context, engine::Loads& loads) const override;
  std::optional<engine::ForceSupport> Support() const override;
  bool CalcLoadJacobians(const engine::ForceContext& context, Eigen::Ref<MatX> K,
                         Eigen::Ref<MatX> D) const override;
  double CalcPotentialEnergy(const engine::ForceContext& context) const override;
  /// One column "<name>_Force": CalcForce (OpenSim's getRecordLabels).
  std::vector<std::string> RecordLabels(const engine::System& system) const override;
  void CalcRecordValues(const engine::ForceContext& context,
                        std::vector<double>& values) const override;

 private:
  std::string name_;
  int coordinate_;
  double stiffness_, rest_length_, viscosity_;
};

}  // namespace sinew::forces

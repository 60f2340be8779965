// The engine element of every force that pulls along a GeometryPath with one excitation:
// OpenSim's PathActuator (tension = optimal_force * excitation) and its muscles (the tension
// of a TensionModel with activation and fiber states). It evaluates the path on the engine
// State (EnginePath), asks its model for the tension and the state derivatives, and applies
// tension * the path's loads.
#pragma once

#include <sinew/forces/actuator.h>
#include <sinew/muscles/engine_path.h>
#include <sinew/muscles/tension_model.h>

#include <memory>
#include <string>
#include <vector>

namespace sinew::muscles {

/// OpenSim's PathActuator: tension = optimal_force * excitation (N), no state.
class IdealPathTension final : public TensionModel {
 public:
  explicit IdealPathTension(double optimal_force) : optimal_force_(optimal_force) {}
  MuscleQuantities Calc(Eigen::Ref<const VecX> z, double excitation,
                        const PathKinematics& path) const override;

 private:
  double optimal_force_;
};

/// A path, its tension model and one excitation input.
class PathActuator final : public forces::Actuator {
 public:
  /// `equilibrate`: InitializeStateVariables solves muscle-tendon equilibrium (OpenSim's
  /// equilibrateMuscles); otherwise the state variables keep their values (file defaults or
  /// loaded states).
  PathActuator(std::string name, double optimal_force, EnginePath path,
               std::shared_ptr<const TensionModel> model, bool equilibrate);

  const EnginePath& path() const { return path_; }
  const TensionModel& model() const { return *model_; }

  std::vector<std::string> StateVariableNames() const override;
  void SetDefaultStateVariables(Eigen::Ref<VecX> z) const override;
  void InitializeStateVariables(const engine::ForceContext& context,
                                Eigen::Ref<VecX> z) const override;
  void CalcStateVariableDerivatives(const engine::ForceContext& context,
                                    Eigen::Ref<VecX> zdot) const override;
  void AddLoads(const engine::ForceContext& context, engine::Loads& loads) const override;
  /// The two above with the path's course and the muscle's quantities computed once.
  void AddLoadsAndStateVariableDerivatives(const engine::ForceContext& context,
                                           engine::Loads& loads,
                                           Eigen::Ref<VecX> zdot) const override;
  std::optional<engine::ForceSupport> Support() const override { return path_.Support(); }

  /// The model's quantities at the context's state (path kinematics included).
  MuscleQuantities CalcQuantities(const engine::ForceContext& context) const;
  /// The path's length and lengthening speed at the context's state.
  PathKinematics CalcPathKinematics(const engine::ForceContext& context) const;

  /// One column, the actuator's name: the tension (OpenSim's actuation; a muscle's tendon force).
  void CalcRecordValues(const engine::ForceContext& context,
                        std::vector<double>& values) const override;

 private:
  Eigen::Map<const VecX> StateVariables(const engine::ForceContext& context) const;
  /// The path's course and the muscle's quantities at the context's state, then the state
  /// variables' derivatives into `zdot` and the tendon force's loads into `loads`, each when
  /// not null: the one computation behind the three calls above.
  void Evaluate(const engine::ForceContext& context, engine::Loads* loads,
                Eigen::Ref<VecX>* zdot) const;

  EnginePath path_;
  std::shared_ptr<const TensionModel> model_;
  int num_z_;
  bool equilibrate_;
};

}  // namespace sinew::muscles

// OpenSim's PathSpring: a spring along a GeometryPath that only pulls. Tension =
// stiffness * max(L - resting_length, 0) * (1 + dissipation * dL/dt), no excitation.
#pragma once

#include <sinew/engine/force_element.h>
#include <sinew/muscles/engine_path.h>

#include <string>
#include <vector>

namespace sinew::muscles {

/// A path spring: stiffness in N/m, resting_length in m, dissipation in s/m.
class PathSpring final : public engine::ForceElement {
 public:
  PathSpring(std::string name, EnginePath path, double resting_length, double stiffness,
             double dissipation);

  std::string name() const override { return name_; }
  void AddLoads(const engine::ForceContext& context, engine::Loads& loads) const override;
  std::optional<engine::ForceSupport> Support() const override { return path_.Support(); }
  /// Elastic energy stiffness * stretch^2 / 2 (the dissipation stores none).
  double CalcPotentialEnergy(const engine::ForceContext& context) const override;
  /// One column, the spring's name: its tension (N).
  std::vector<std::string> RecordLabels(const engine::System& system) const override;
  void CalcRecordValues(const engine::ForceContext& context,
                        std::vector<double>& values) const override;

  /// Tension (N) at a path length and lengthening speed.
  double CalcTension(const PathKinematics& path) const;

 private:
  std::string name_;
  EnginePath path_;
  double resting_length_, stiffness_, dissipation_;
};

}  // namespace sinew::muscles

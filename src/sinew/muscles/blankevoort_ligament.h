// OpenSim's Blankevoort1991Ligament (opensim-jam, Smith et al. 2016): a passive path force whose
// spring is zero while slack, quadratic in strain in the toe region and linear beyond the
// transition strain (continuous force and slope there), plus a damping term that only acts while
// the ligament is stretched and lengthening. The total tension is never negative.
#pragma once

#include <sinew/engine/force_element.h>
#include <sinew/muscles/engine_path.h>

#include <optional>
#include <string>
#include <vector>

namespace sinew::muscles {

/// The ligament's parameters, with OpenSim's names and defaults.
struct BlankevoortParameters {
  double linear_stiffness = 1.0;       ///< slope of the linear region, N per unit strain
  double transition_strain = 0.06;     ///< strain where the toe region ends (dimensionless)
  double damping_coefficient = 0.003;  ///< N s per unit strain
  double slack_length = 0.0;           ///< length (m) at which tension starts
};

/// The ligament's forces at one path length and lengthening speed (N), and its strains.
struct LigamentForces {
  double strain = 0, strain_rate = 0;  ///< (L - L0) / L0 and dL/dt / L0 (1/s)
  double spring = 0, damping = 0, total = 0;
};

/// A parameter out of range: its property name and why.
struct BadParameter {
  std::string property;
  std::string message;
};
/// The first parameter out of range (negative stiffness or damping, a transition strain or
/// slack length that is not positive), or nullopt.
std::optional<BadParameter> FindBadParameter(const BlankevoortParameters& p);

/// Spring force (N) at a strain: 0 for strain <= 0, k e^2 / (2 e_t) for 0 < e < e_t,
/// k (e - e_t / 2) beyond.
double BlankevoortSpringForce(const BlankevoortParameters& p, double strain);
/// Elastic energy (J) at a strain: the integral of the spring force over length, L0 * int f de.
double BlankevoortPotentialEnergy(const BlankevoortParameters& p, double strain);
/// All the forces at a path length and lengthening speed (OpenSim's damping: c * strain_rate
/// when stretched and lengthening, faded in by a quintic smooth step over strain 0..0.01).
LigamentForces CalcBlankevoortForces(const BlankevoortParameters& p, const PathKinematics& path);

/// The ligament on its path as an engine force element.
class BlankevoortLigament final : public engine::ForceElement {
 public:
  /// Throws sinew::Error for negative parameters or a slack length that is not positive.
  BlankevoortLigament(std::string name, EnginePath path, const BlankevoortParameters& parameters);

  std::string name() const override { return name_; }
  void AddLoads(const engine::ForceContext& context, engine::Loads& loads) const override;
  std::optional<engine::ForceSupport> Support() const override { return path_.Support(); }
  /// The spring's elastic energy (the damping stores none).
  double CalcPotentialEnergy(const engine::ForceContext& context) const override;
  /// OpenSim's seven columns: <name>.force_spring, .force_damping, .force_total (N), .length (m),
  /// .lengthening_speed (m/s), .strain, .strain_rate (1/s).
  std::vector<std::string> RecordLabels(const engine::System& system) const override;
  void CalcRecordValues(const engine::ForceContext& context,
                        std::vector<double>& values) const override;

  const BlankevoortParameters& parameters() const { return parameters_; }

 private:
  std::string name_;
  EnginePath path_;
  BlankevoortParameters parameters_;
};

}  // namespace sinew::muscles

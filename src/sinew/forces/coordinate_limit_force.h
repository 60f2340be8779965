// OpenSim's CoordinateLimitForce: a one-sided spring and damper that act on a coordinate beyond
// its upper or lower limit, switched on smoothly over a transition band.
#pragma once

#include <sinew/engine/force_element.h>

#include <string>

namespace sinew::forces {

/// The parameters in OpenSim's units: for a rotational coordinate the limits and the transition
/// are in degrees, the stiffnesses in N m/degree and the damping in N m s/degree; for a
/// translational one in m, N/m and N s/m (OpenSim's CoordinateLimitForce::extendConnectToModel
/// converts them with w = pi/180 or 1).
struct CoordinateLimitParameters {
  double upper_stiffness = 1.0;
  double upper_limit = 0.0;
  double lower_stiffness = 1.0;
  double lower_limit = 0.0;
  double damping = 0.001;
  double transition = 0.1;
};

/// With q_up = w upper_limit, q_lo = w lower_limit, dq = w transition, K_up = upper_stiffness /
/// w, K_lo = lower_stiffness / w, c = damping / w (SI), s(x) = 10x^3 - 15x^4 + 6x^5 clamped to
/// [0, 1] (Simbody's Function::Step):
///   k_up(q) = K_up s((q - q_up) / dq),   k_lo(q) = K_lo s((q_lo - q) / dq),
///   f = -k_up (q - q_up) + k_lo (q_lo - q) - c (k_up / K_up + k_lo / K_lo) u.
/// Potential energy: the integral of the stiffness parts, K dq^2 x^5 (2 - 5x/2 + 6x^2/7) inside
/// the band (x = depth / dq) and K (depth^2 / 2 - dq^2 / 7) past it, as OpenSim's
/// computePotentialEnergy. A zero K_up or K_lo disables that side's damping too (OpenSim would
/// divide zero by zero).
class CoordinateLimitForce final : public engine::ForceElement {
 public:
  /// `rotational`: the coordinate's OpenSim motion type is Rotational (w = pi/180).
  CoordinateLimitForce(std::string name, int coordinate, bool rotational,
                       const CoordinateLimitParameters& parameters);

  std::string name() const override { return name_; }
  /// The generalized force (N m or N) at coordinate value q and speed u.
  double CalcForce(double q, double u) const;
  /// The potential energy (J) at coordinate value q.
  double CalcPotentialEnergy(double q) const;

  void AddLoads(const engine::ForceContext& context, engine::Loads& loads) const override;
  std::optional<engine::ForceSupport> Support() const override;
  bool CalcLoadJacobians(const engine::ForceContext& context, Eigen::Ref<MatX> K,
                         Eigen::Ref<MatX> D) const override;
  double CalcPotentialEnergy(const engine::ForceContext& context) const override;
  /// Two columns, "<name>" (the generalized force) and "PotentialEnergy" (OpenSim's labels:
  /// the second is not prefixed, so two limit forces repeat it).
  std::vector<std::string> RecordLabels(const engine::System& system) const override;
  void CalcRecordValues(const engine::ForceContext& context,
                        std::vector<double>& values) const override;

 private:
  // The upper and lower stiffnesses k_up(q), k_lo(q) and their derivatives by q.
  struct Stiffness {
    double up, lo, dup, dlo;
  };
  Stiffness CalcStiffness(double q) const;
  // c (k_up / K_up + k_lo / K_lo) and its derivative by q.
  double DampingFactor(const Stiffness& k) const;
  double DampingFactorDerivative(const Stiffness& k) const;

  std::string name_;
  int coordinate_;
  double q_up_, q_lo_, dq_, k_up_, k_lo_, c_;
};

}  // namespace sinew::forces

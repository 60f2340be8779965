// OpenSim 4's RigidTendonMuscle as a TensionModel: no state variables. The tendon keeps its
// slack length, the fiber spans the rest of the path at constant width, its velocity is the
// path's lengthening speed, and the activation is the excitation itself. Tension = (a fal fv +
// fpe) Fiso cos(pennation) with the file's (or OpenSim's default) spline curves.
// docs/muscles.md#rigidtendonmuscle.
#pragma once

#include <sinew/functions/function.h>
#include <sinew/muscles/tension_model.h>
#include <sinew/muscles/thelen2003_muscle.h>

namespace sinew::muscles {

/// A RigidTendonMuscle's properties (OpenSim's names and defaults).
struct RigidTendonParameters {
  MuscleParameters muscle;
  functions::FunctionPtr active_force_length_curve;   ///< fiber length / optimal -> multiplier
  functions::FunctionPtr passive_force_length_curve;  ///< fiber length / optimal -> force / Fiso
  functions::FunctionPtr force_velocity_curve;        ///< velocity / (vmax optimal) -> multiplier
};

/// The rigid-tendon muscle.
class RigidTendonMuscle final : public TensionModel {
 public:
  /// Missing curves take OpenSim's defaults (simm_muscle_curves.h). Throws sinew::Error
  /// (message only) for an optimal fiber length or maximum contraction velocity that is not
  /// positive.
  explicit RigidTendonMuscle(RigidTendonParameters parameters);

  MuscleQuantities Calc(Eigen::Ref<const VecX> z, double excitation,
                        const PathKinematics& path) const override;

  const RigidTendonParameters& parameters() const { return p_; }

 private:
  RigidTendonParameters p_;
  double width_;  ///< m: optimal_fiber_length sin(pennation_angle_at_optimal)
};

}  // namespace sinew::muscles

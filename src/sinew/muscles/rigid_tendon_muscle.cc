#include <sinew/common/error.h>
#include <sinew/muscles/rigid_tendon_muscle.h>
#include <sinew/muscles/simm_muscle_curves.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace sinew::muscles {

RigidTendonMuscle::RigidTendonMuscle(RigidTendonParameters parameters) : p_(std::move(parameters)) {
  if (!(p_.muscle.optimal_fiber_length > 0.0) || !(p_.muscle.max_contraction_velocity > 0.0)) {
    throw Error(SourceLocation{}, "",
                "optimal_fiber_length and max_contraction_velocity must be greater than zero");
  }
  if (!p_.active_force_length_curve)
    p_.active_force_length_curve = MakeDefaultActiveForceLengthCurve();
  if (!p_.passive_force_length_curve)
    p_.passive_force_length_curve = MakeDefaultPassiveForceLengthCurve();
  if (!p_.force_velocity_curve) p_.force_velocity_curve = MakeDefaultForceVelocityCurve();
  width_ = p_.muscle.optimal_fiber_length * std::sin(p_.muscle.pennation_angle_at_optimal);
}

MuscleQuantities RigidTendonMuscle::Calc(Eigen::Ref<const VecX> /*z*/, double excitation,
                                         const PathKinematics& path) const {
  const MuscleParameters& m = p_.muscle;
  MuscleQuantities out;
  out.activation = excitation;
  out.tendon_length = m.tendon_slack_length;
  // The fiber's projection on the path, never negative; with a width the fiber is the
  // hypotenuse (OpenSim treats widths below sqrt(eps) as none).
  const double along = std::max(path.length - m.tendon_slack_length, 0.0);
  double cosine = 1.0;
  out.fiber_length = along;
  if (width_ > std::sqrt(std::numeric_limits<double>::epsilon())) {
    out.fiber_length = std::hypot(along, width_);
    cosine = along / out.fiber_length;
  }
  out.pennation_angle = std::acos(cosine);
  // OpenSim takes the path's lengthening speed as the fiber velocity (not its share along the
  // fiber), normalized by max_contraction_velocity optimal fiber lengths per second.
  out.fiber_velocity = path.lengthening_speed;
  const double lceN = out.fiber_length / m.optimal_fiber_length;
  const double vN = out.fiber_velocity / (m.optimal_fiber_length * m.max_contraction_velocity);
  const double fal = p_.active_force_length_curve->Calc(lceN);
  const double fpe = std::clamp(p_.passive_force_length_curve->Calc(lceN), 0.0, 10.0);
  const double fv = p_.force_velocity_curve->Calc(vN);
  out.active_fiber_force = m.max_isometric_force * excitation * fal * fv;
  out.passive_fiber_force = m.max_isometric_force * fpe;
  out.tendon_force = (out.active_fiber_force + out.passive_fiber_force) * cosine;
  return out;
}

}  // namespace sinew::muscles

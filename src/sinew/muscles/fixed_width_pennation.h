// OpenSim's MuscleFixedWidthPennationModel: the fibers and the tendon form a parallelogram of
// constant height h = optimal_fiber_length sin(pennation_angle_at_optimal), so a fiber of length
// l has pennation angle asin(h / l), capped at maximum_pennation_angle.
#pragma once

namespace sinew::muscles {

/// The constant-thickness pennation model. Lengths in m, angles in rad, speeds in m/s.
class FixedWidthPennation {
 public:
  /// Throws sinew::Error for an optimal fiber length <= 0, a pennation angle at optimal outside
  /// [0, pi/2), or a maximum pennation angle outside [0, pi/2].
  FixedWidthPennation(double optimal_fiber_length, double pennation_angle_at_optimal,
                      double maximum_pennation_angle);

  /// h, the parallelogram's constant height.
  double parallelogram_height() const { return height_; }
  /// The shortest fiber the model allows: h / sin(maximum angle) (1% of the optimal length when
  /// the maximum angle is 0).
  double minimum_fiber_length() const { return minimum_fiber_length_; }
  /// That fiber's length along the tendon: minimum_fiber_length cos(maximum angle).
  double minimum_fiber_length_along_tendon() const { return minimum_along_tendon_; }
  /// The fiber length raised to the minimum fiber length.
  double ClampFiberLength(double fiber_length) const;

  /// asin(h / l), the maximum angle for fibers at or below the minimum length, 0 for a muscle
  /// without pennation.
  double PennationAngle(double fiber_length) const;
  /// The fiber length that leaves `tendon_length` of the musculotendon length:
  /// sqrt(h^2 + (muscle_length - tendon_length)^2), or the minimum length when the fiber's part
  /// along the tendon is shorter than the minimum's.
  double FiberLength(double muscle_length, double tendon_length) const;
  /// d(phi)/d(l) = -(h / l^2) / sqrt(1 - (h / l)^2), for l > h.
  double DPennationAngleDFiberLength(double fiber_length) const;
  /// d(phi)/dt = -(v / l) tan(phi) (0 for a muscle without pennation).
  double PennationAngularVelocity(double tan_phi, double fiber_length, double fiber_velocity) const;

 private:
  double pennation_at_optimal_;
  double maximum_angle_;
  double height_;
  double maximum_sin_;
  double minimum_fiber_length_;
  double minimum_along_tendon_;
};

}  // namespace sinew::muscles

// Pennation with a constant muscle thickness (OpenSim's MuscleFixedWidthPennationModel): the
// fibers keep the height h = optimal_fiber_length * sin(pennation_angle_at_optimal) of the
// parallelogram they span, so sin(phi) = h / fiber_length, capped at the maximum pennation
// angle; the fiber length never goes below h / sin(maximum_pennation_angle) (or 1% of the
// optimal length for a muscle that may not pennate).
#pragma once

namespace sinew::muscles {

/// The fixed-width pennation model of one muscle. Lengths in m, angles in rad.
class FixedWidthPennation {
 public:
  /// Throws sinew::Error (message only; the builder adds file and component) for an optimal
  /// fiber length <= 0 or angles outside [0, pi/2).
  FixedWidthPennation(double optimal_fiber_length, double pennation_angle_at_optimal,
                      double maximum_pennation_angle);

  double height() const { return height_; }
  double minimum_fiber_length() const { return minimum_fiber_length_; }
  /// The fiber length raised to the minimum fiber length.
  double ClampFiberLength(double fiber_length) const;
  /// phi at a fiber length (the maximum angle at or below the minimum length).
  double PennationAngle(double fiber_length) const;
  /// The fiber length whose projection along the tendon is muscle_length - tendon_length (the
  /// minimum fiber length when that projection is shorter than the minimum's).
  double FiberLength(double muscle_length, double tendon_length) const;

 private:
  double pennation_at_optimal_, maximum_pennation_;
  double height_, maximum_sin_, minimum_fiber_length_;
};

}  // namespace sinew::muscles

// OpenSim's ideal actuators: a force, torque or generalized force equal to
// optimal_force x excitation, the excitation being the actuator's input. As in OpenSim, min_control
// and max_control do not clamp the excitation in a forward simulation (OpenSim's
// CoordinateActuator, PointActuator and TorqueActuator::computeActuation return control x
// optimal_force; the bounds serve solvers such as Static Optimization and CMC).
#pragma once

#include <sinew/engine/loads.h>
#include <sinew/math/types.h>

#include <limits>
#include <string>
#include <vector>

namespace sinew::forces {

/// The part every actuator shares: a name, a gain, and one input, its excitation (control)
/// e, read from State::inputs at every evaluation (set by a Controller such as
/// ExcitationController, or held in the state).
class Actuator : public engine::ForceElement {
 public:
  Actuator(std::string name, double optimal_force);

  std::string name() const override { return name_; }
  /// One input, "excitation" (dimensionless).
  std::vector<std::string> InputNames() const override { return {"excitation"}; }
  double optimal_force() const { return optimal_force_; }

  /// OpenSim's min_control / max_control (dimensionless): kept for reporting, not applied to
  /// e (see the file comment). Throws sinew::Error when min_control > max_control.
  void SetControlRange(double min_control, double max_control);
  double min_control() const { return min_control_; }
  double max_control() const { return max_control_; }

  /// optimal_force * e, with e the actuator's input in `context`: N for forces, N m for torques.
  double CalcActuation(const engine::ForceContext& context) const;

  /// One column, the actuator's name: CalcActuation (OpenSim's Actuator::getRecordLabels).
  std::vector<std::string> RecordLabels(const engine::System& system) const override;
  void CalcRecordValues(const engine::ForceContext& context,
                        std::vector<double>& values) const override;

 private:
  std::string name_;
  double optimal_force_;
  double min_control_ = -std::numeric_limits<double>::infinity();
  double max_control_ = std::numeric_limits<double>::infinity();
};

/// PointActuator: a force of magnitude CalcActuation(t) along `direction` (made unit) on
/// `body`, applied at `point`. The direction is in ground when `force_is_global`, else in the
/// body frame B; the point is in ground when `point_is_global` (then the force acts at the body
/// point that is at that ground location at each instant), else in B.
class PointActuator : public Actuator {
 public:
  PointActuator(std::string name, double optimal_force, int body, const Vec3& point,
                bool point_is_global, const Vec3& direction, bool force_is_global);
  void AddLoads(const engine::ForceContext& context, engine::Loads& loads) const override;

 private:
  int body_;
  Vec3 point_;
  bool point_is_global_;
  Vec3 unit_direction_;
  bool force_is_global_;
};

/// TorqueActuator: torque CalcActuation(t) * unit(axis) on `body_a` and its opposite on
/// `body_b` (OpenSim's order). The axis is in ground when `torque_is_global`, else in body A's
/// frame.
class TorqueActuator : public Actuator {
 public:
  TorqueActuator(std::string name, double optimal_force, int body_a, int body_b, const Vec3& axis,
                 bool torque_is_global);
  void AddLoads(const engine::ForceContext& context, engine::Loads& loads) const override;

 private:
  int body_a_;
  int body_b_;
  Vec3 unit_axis_;
  bool torque_is_global_;
};

/// CoordinateActuator: generalized force CalcActuation(t) on coordinate `coordinate`
/// (N m on a rotational coordinate, N on a translational one).
class CoordinateActuator : public Actuator {
 public:
  CoordinateActuator(std::string name, double optimal_force, int coordinate);
  void AddLoads(const engine::ForceContext& context, engine::Loads& loads) const override;

 private:
  int coordinate_;
};

}  // namespace sinew::forces

#include <sinew/common/error.h>
#include <sinew/engine/pose.h>
#include <sinew/engine/state.h>
#include <sinew/forces/actuator.h>

#include <utility>

namespace sinew::forces {
namespace {

// A unit vector along `v`; a zero vector is an error because OpenSim would divide by zero.
Vec3 UnitOrThrow(const Vec3& v, const std::string& actuator, const char* what) {
  const double n = v.norm();
  if (!(n > 0.0)) {
    throw Error(SourceLocation{}, actuator, std::string(what) + " is the zero vector");
  }
  return v / n;
}

}  // namespace

Actuator::Actuator(std::string name, double optimal_force)
    : name_(std::move(name)), optimal_force_(optimal_force) {}

void Actuator::SetControlRange(double min_control, double max_control) {
  if (min_control > max_control) {
    throw Error(SourceLocation{}, name_, "min_control is larger than max_control");
  }
  min_control_ = min_control;
  max_control_ = max_control;
}

double Actuator::CalcActuation(const engine::ForceContext& context) const {
  return optimal_force_ * context.input(0);
}

std::vector<std::string> Actuator::RecordLabels(const engine::System& /*system*/) const {
  return {name_};
}

void Actuator::CalcRecordValues(const engine::ForceContext& context,
                                std::vector<double>& values) const {
  values.push_back(CalcActuation(context));
}

PointActuator::PointActuator(std::string name, double optimal_force, int body, const Vec3& point,
                             bool point_is_global, const Vec3& direction, bool force_is_global)
    : Actuator(std::move(name), optimal_force),
      body_(body),
      point_(point),
      point_is_global_(point_is_global),
      unit_direction_(UnitOrThrow(direction, this->name(), "direction")),
      force_is_global_(force_is_global) {}

void PointActuator::AddLoads(const engine::ForceContext& context, engine::Loads& loads) const {
  const engine::State& state = context.state;
  const double f = CalcActuation(context);
  if (f == 0.0) return;
  const Transform X_GB = engine::PoseOf(state.bodies[body_]);
  const Vec3 f_G = f * (force_is_global_ ? unit_direction_ : Vec3(X_GB.R * unit_direction_));
  const Vec3 p_BQ = point_is_global_ ? Vec3(X_GB.Inverse() * point_) : point_;
  loads.AddForceAtPoint(state, body_, p_BQ, f_G);
}

TorqueActuator::TorqueActuator(std::string name, double optimal_force, int body_a, int body_b,
                               const Vec3& axis, bool torque_is_global)
    : Actuator(std::move(name), optimal_force),
      body_a_(body_a),
      body_b_(body_b),
      unit_axis_(UnitOrThrow(axis, this->name(), "axis")),
      torque_is_global_(torque_is_global) {}

void TorqueActuator::AddLoads(const engine::ForceContext& context, engine::Loads& loads) const {
  const engine::State& state = context.state;
  const double torque = CalcActuation(context);
  if (torque == 0.0) return;
  const Vec3 axis_G =
      torque_is_global_ ? unit_axis_ : Vec3(engine::PoseOf(state.bodies[body_a_]).R * unit_axis_);
  // AddTorqueBetween(x, y, tau) puts +tau on y and -tau on x: here +tau on A, -tau on B.
  loads.AddTorqueBetween(body_b_, body_a_, torque * axis_G);
}

CoordinateActuator::CoordinateActuator(std::string name, double optimal_force, int coordinate)
    : Actuator(std::move(name), optimal_force), coordinate_(coordinate) {}

void CoordinateActuator::AddLoads(const engine::ForceContext& context, engine::Loads& loads) const {
  const double f = CalcActuation(context);
  if (f != 0.0) loads.AddGeneralizedForce(coordinate_, f);
}

}  // namespace sinew::forces

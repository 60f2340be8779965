#include <sinew/engine/loads.h>
#include <sinew/engine/pose.h>
#include <sinew/engine/state.h>
#include <sinew/forces/prescribed_force.h>

#include <utility>

namespace sinew::forces {
namespace {

Vec3 Evaluate(const VectorOfTime& functions, double t) {
  return {functions[0]->Calc(t), functions[1]->Calc(t), functions[2]->Calc(t)};
}

}  // namespace

PrescribedForce::PrescribedForce(std::string name, int body, const Transform& X_BF,
                                 PrescribedForceParameters parameters)
    : name_(std::move(name)), body_(body), X_BF_(X_BF), parameters_(std::move(parameters)) {}

void PrescribedForce::AddLoads(const engine::ForceContext& context, engine::Loads& loads) const {
  const engine::State& state = context.state;
  const double t = state.t;
  const Transform X_GB = engine::PoseOf(state.bodies[body_]);
  const Mat3 R_GF = X_GB.R * X_BF_.R;
  if (parameters_.force) {
    Vec3 f_G = Evaluate(*parameters_.force, t);
    if (!parameters_.force_is_global) f_G = R_GF * f_G;
    Vec3 p_BQ = X_BF_.p;  // the frame's origin
    if (parameters_.point) {
      const Vec3 point = Evaluate(*parameters_.point, t);
      p_BQ = parameters_.point_is_global ? X_GB.Inverse() * point : X_BF_ * point;
    }
    loads.AddForceAtPoint(state, body_, p_BQ, f_G);
  }
  if (parameters_.torque) {
    Vec3 tau_G = Evaluate(*parameters_.torque, t);
    if (!parameters_.force_is_global) tau_G = R_GF * tau_G;
    loads.AddTorque(body_, tau_G);
  }
}

std::optional<engine::ForceSupport> PrescribedForce::Support() const {
  engine::ForceSupport support;
  if (body_ != 0) support.bodies.push_back(body_);
  return support;
}

}  // namespace sinew::forces

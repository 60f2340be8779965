#include <sinew/common/error.h>
#include <sinew/engine/loads.h>
#include <sinew/engine/pose.h>
#include <sinew/engine/state.h>
#include <sinew/forces/external_force.h>

#include <utility>

namespace sinew::forces {
namespace {

Vec3 CalcAt(const std::array<functions::FunctionPtr, 3>& f, double t) {
  return Vec3(f[0]->Calc(t), f[1]->Calc(t), f[2]->Calc(t));
}

bool AllSet(const std::array<functions::FunctionPtr, 3>& f) { return f[0] && f[1] && f[2]; }
bool NoneSet(const std::array<functions::FunctionPtr, 3>& f) { return !f[0] && !f[1] && !f[2]; }

}  // namespace

ExternalForce::ExternalForce(std::string name, std::string body_label,
                             const ExternalForceBodies& bodies, ExternalForceFunctions functions)
    : name_(std::move(name)),
      body_label_(std::move(body_label)),
      bodies_(bodies),
      functions_(std::move(functions)) {
  for (const auto* part : {&functions_.force, &functions_.point, &functions_.torque}) {
    if (!AllSet(*part) && !NoneSet(*part)) {
      throw Error("ExternalForce '" + name_ + "': a part needs all three functions or none");
    }
  }
  if (!applies_force() && !applies_torque()) {
    throw Error("ExternalForce '" + name_ + "' applies neither a force nor a torque");
  }
  if (!applies_force() && specifies_point()) {
    throw Error("ExternalForce '" + name_ + "' gives a point but no force");
  }
}

ExternalForce::Applied ExternalForce::Calc(const engine::ForceContext& context) const {
  const engine::State& s = context.state;
  const double t = s.t;
  const Transform X_GE = engine::PoseOf(s.bodies[bodies_.force_in]);
  Applied applied;
  if (applies_force()) {
    applied.f_G = X_GE.R * CalcAt(functions_.force, t);
    if (specifies_point()) {
      const Vec3 p_GQ = engine::PoseOf(s.bodies[bodies_.point_in]) * CalcAt(functions_.point, t);
      applied.p_BQ = engine::PoseOf(s.bodies[bodies_.applied_to]).Inverse() * p_GQ;
    }
  }
  if (applies_torque()) applied.tau_G = X_GE.R * CalcAt(functions_.torque, t);
  return applied;
}

void ExternalForce::AddLoads(const engine::ForceContext& context, engine::Loads& loads) const {
  const Applied applied = Calc(context);
  if (applies_force()) {
    loads.AddForceAtPoint(context.state, bodies_.applied_to, applied.p_BQ, applied.f_G);
  }
  if (applies_torque()) loads.AddTorque(bodies_.applied_to, applied.tau_G);
}

std::optional<engine::ForceSupport> ExternalForce::Support() const {
  engine::ForceSupport support;
  for (int b : {bodies_.applied_to, bodies_.force_in, bodies_.point_in}) {
    if (b == 0) continue;
    bool seen = false;
    for (int s : support.bodies) seen = seen || s == b;
    if (!seen) support.bodies.push_back(b);
  }
  return support;
}

std::vector<std::string> ExternalForce::RecordLabels(const engine::System& /*system*/) const {
  const std::string prefix = body_label_ + "_" + name_ + "_";
  std::vector<std::string> labels;
  auto add = [&](const char* a, const char* b, const char* c) {
    for (const char* suffix : {a, b, c}) labels.push_back(prefix + suffix);
  };
  if (applies_force()) add("Fx", "Fy", "Fz");
  if (specifies_point()) add("px", "py", "pz");
  if (applies_torque()) add("Tx", "Ty", "Tz");
  return labels;
}

void ExternalForce::CalcRecordValues(const engine::ForceContext& context,
                                     std::vector<double>& values) const {
  const Applied applied = Calc(context);
  auto add = [&](const Vec3& v) { values.insert(values.end(), v.begin(), v.end()); };
  if (applies_force()) add(applied.f_G);
  if (specifies_point()) add(applied.p_BQ);
  if (applies_torque()) add(applied.tau_G);
}

}  // namespace sinew::forces

// Builder of OpenSim's PrescribedForce: a frame (4.x socket_frame, 3.x body) and three optional
// FunctionSets of time.
#include <sinew/forces/prescribed_force.h>
#include <sinew/model/element_values.h>
#include <sinew/opensim/internal/force_registry.h>

namespace sinew::opensim::internal {
namespace {

// A FunctionSet property: none when empty; three functions, else an error (as OpenSim).
std::optional<forces::VectorOfTime> VectorOfTimeOf(const ForceBuildInput& in,
                                                   const std::string& property) {
  const auto it = in.force.functions.find(property);
  if (it == in.force.functions.end() || it->second.empty()) return std::nullopt;
  if (it->second.size() != 3) {
    in.values.Fail("<" + property + "> has " + std::to_string(it->second.size()) +
                   " functions; PrescribedForce needs all three components or none");
  }
  return forces::VectorOfTime{it->second[0], it->second[1], it->second[2]};
}

}  // namespace

std::shared_ptr<engine::ForceElement> BuildPrescribedForce(const ForceBuildInput& in) {
  const model::ElementValues& v = in.values;
  int body = 0;
  Transform X_BF;
  if (in.force.frames.count("frame") != 0 || !v.Has("body")) {
    std::tie(body, X_BF) = MapFrame(in, "frame");
  } else {
    body = MapBody(in.spec, v, v.String("body"), in.body_map, "body");  // 3.x
  }
  forces::PrescribedForceParameters p;
  p.force = VectorOfTimeOf(in, "forceFunctions");
  p.point = VectorOfTimeOf(in, "pointFunctions");
  p.torque = VectorOfTimeOf(in, "torqueFunctions");
  p.force_is_global = v.Bool("forceIsGlobal", p.force_is_global);
  p.point_is_global = v.Bool("pointIsGlobal", p.point_is_global);
  return std::make_shared<forces::PrescribedForce>(in.force.name, body, X_BF, std::move(p));
}

}  // namespace sinew::opensim::internal

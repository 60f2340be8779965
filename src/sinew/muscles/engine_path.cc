#include <sinew/common/error.h>
#include <sinew/engine/pose.h>
#include <sinew/muscles/engine_path.h>

#include <algorithm>

namespace sinew::muscles {
namespace {

void AddUnique(std::vector<std::pair<int, int>>& list, int spec_index, int engine_index) {
  const std::pair<int, int> entry{spec_index, engine_index};
  if (std::find(list.begin(), list.end(), entry) == list.end()) list.push_back(entry);
}

}  // namespace

EnginePath::EnginePath(paths::GeometryPath path, int num_spec_bodies, int num_spec_coordinates,
                       const std::vector<int>& body_map, const std::vector<int>& coordinate_map)
    : path_(std::move(path)),
      num_spec_bodies_(num_spec_bodies),
      num_spec_coordinates_(num_spec_coordinates) {
  auto map_body = [&](int spec_body) {
    if (spec_body < 0 || spec_body >= static_cast<int>(body_map.size()) ||
        body_map[spec_body] < 0) {
      throw Error(path_.where(), path_.component(), "the path uses a body that is not simulated");
    }
    AddUnique(bodies_, spec_body, body_map[spec_body]);
  };
  auto map_coordinate = [&](int spec_coordinate) {
    if (spec_coordinate == model::kNone) return;
    if (spec_coordinate < 0 || spec_coordinate >= static_cast<int>(coordinate_map.size()) ||
        coordinate_map[spec_coordinate] < 0) {
      throw Error(path_.where(), path_.component(),
                  "the path reads a coordinate that is not simulated");
    }
    AddUnique(coordinates_, spec_coordinate, coordinate_map[spec_coordinate]);
  };
  for (const paths::PathPoint& point : path_.points()) {
    map_body(point.body);
    map_coordinate(point.coordinate);
    for (int c : point.coordinates) map_coordinate(c);
  }
  for (const paths::PathWrap& wrap : path_.wraps()) map_body(wrap.body);
  if (const model::FunctionBasedPathSpec* f = path_.function_path()) {
    for (int c : f->coordinates) map_coordinate(c);
  }
}

PathScratch& EnginePath::Scratch() {
  thread_local PathScratch scratch;
  return scratch;
}

PathKinematics EnginePath::Calc(const engine::State& state, PathScratch& scratch) const {
  // Sized once per thread to the largest model seen; only the path's entries are written.
  if (static_cast<int>(scratch.X_GB.size()) < num_spec_bodies_) {
    scratch.X_GB.resize(num_spec_bodies_);
    scratch.V_GB.resize(num_spec_bodies_, SpatialVec::Zero());
  }
  if (static_cast<int>(scratch.q.size()) < num_spec_coordinates_) {
    scratch.q.resize(num_spec_coordinates_, 0.0);
    scratch.u.resize(num_spec_coordinates_, 0.0);
  }
  for (const auto& [spec_body, engine_body] : bodies_) {
    const engine::BodyState& body = state.bodies[engine_body];
    scratch.X_GB[spec_body] = engine::PoseOf(body);
    scratch.V_GB[spec_body] << body.w_GB, body.v_GB;
  }
  for (const auto& [spec_coordinate, engine_coordinate] : coordinates_) {
    scratch.q[spec_coordinate] = state.q[engine_coordinate];
    scratch.u[spec_coordinate] = state.u[engine_coordinate];
  }
  const std::span<const Transform> X_GB(scratch.X_GB.data(), num_spec_bodies_);
  path_.CalcState(std::span<const double>(scratch.q.data(), num_spec_coordinates_), X_GB,
                  scratch.path);
  PathKinematics kinematics;
  kinematics.length = scratch.path.length;
  kinematics.lengthening_speed = paths::CalcLengtheningSpeed(
      scratch.path, X_GB, std::span<const SpatialVec>(scratch.V_GB.data(), num_spec_bodies_),
      std::span<const double>(scratch.u.data(), num_spec_coordinates_));
  return kinematics;
}

void EnginePath::AddTensionLoads(const engine::State& state, double tension, PathScratch& scratch,
                                 engine::Loads& loads) const {
  if (tension == 0.0) return;
  const std::span<const Transform> X_GB(scratch.X_GB.data(), num_spec_bodies_);
  paths::CalcPathLoads(scratch.path, X_GB, tension, scratch.loads);
  for (const paths::PointForce& f : scratch.loads.point_forces) {
    const auto it = std::find_if(bodies_.begin(), bodies_.end(),
                                 [&](const auto& entry) { return entry.first == f.body; });
    if (it->second == 0) continue;  // ground does not move
    loads.AddForceAtPoint(state, it->second, f.p_BP, f.f_G);
  }
  for (const paths::CoordinateForce& f : scratch.loads.coordinate_forces) {
    const auto it = std::find_if(coordinates_.begin(), coordinates_.end(),
                                 [&](const auto& entry) { return entry.first == f.coordinate; });
    loads.AddGeneralizedForce(it->second, f.value);
  }
}

engine::ForceSupport EnginePath::Support() const {
  engine::ForceSupport support;
  for (const auto& [spec_body, engine_body] : bodies_) {
    if (engine_body != 0) support.bodies.push_back(engine_body);
  }
  for (const auto& [spec_coordinate, engine_coordinate] : coordinates_) {
    support.coordinates.push_back(engine_coordinate);
  }
  return support;
}

}  // namespace sinew::muscles

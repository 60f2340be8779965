// A GeometryPath evaluated on an engine State: the bridge between the paths layer (which works
// in ModelSpec order: spec bodies, spec coordinates) and the engine (System order). It gathers
// the poses and twists of the bodies the path touches and the coordinates its points read,
// computes the path's length and lengthening speed, and applies the loads of a tension.
#pragma once

#include <sinew/engine/force_element.h>
#include <sinew/engine/loads.h>
#include <sinew/engine/state.h>
#include <sinew/paths/geometry_path.h>
#include <sinew/paths/path_loads.h>

#include <utility>
#include <vector>

namespace sinew::muscles {

/// Length (m) and lengthening speed (m/s) of a path at one state.
struct PathKinematics {
  double length = 0.0;
  double lengthening_speed = 0.0;
};

/// Buffers of one path evaluation, reused between evaluations (one per thread: see
/// EnginePath::Scratch). After the first evaluations they hold enough room, and evaluating
/// allocates nothing.
struct PathScratch {
  std::vector<Transform> X_GB;  ///< per spec body (only the path's bodies are set)
  std::vector<SpatialVec> V_GB;
  std::vector<double> q, u;  ///< per spec coordinate (only the path's coordinates are set)
  paths::PathState path;
  paths::PathLoads loads;
};

/// A path bound to an engine System through the spec-to-engine maps of the parser.
class EnginePath {
 public:
  /// `body_map` / `coordinate_map`: spec index -> engine index (OpenSim layer's SpecToSystem).
  /// Throws sinew::Error (path's file, line, component) when a body or coordinate the path
  /// uses is not in the engine system.
  EnginePath(paths::GeometryPath path, int num_spec_bodies, int num_spec_coordinates,
             const std::vector<int>& body_map, const std::vector<int>& coordinate_map);

  const paths::GeometryPath& path() const { return path_; }

  /// The path at `state` (into scratch.path) and its length and lengthening speed.
  PathKinematics Calc(const engine::State& state, PathScratch& scratch) const;
  /// Adds the loads of `tension` (N, positive pulls the ends together) along the path last
  /// computed into `scratch` by Calc at the same state.
  void AddTensionLoads(const engine::State& state, double tension, PathScratch& scratch,
                       engine::Loads& loads) const;

  /// The engine bodies (not ground) and coordinates the path's loads act on.
  engine::ForceSupport Support() const;

  /// This thread's buffers (one set per thread, shared by every path: use it within one call).
  static PathScratch& Scratch();

 private:
  paths::GeometryPath path_;
  int num_spec_bodies_, num_spec_coordinates_;
  std::vector<std::pair<int, int>> bodies_;       ///< (spec, engine) of each body the path uses
  std::vector<std::pair<int, int>> coordinates_;  ///< (spec, engine) of each coordinate it reads
};

}  // namespace sinew::muscles

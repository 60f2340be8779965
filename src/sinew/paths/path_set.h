// Every geometry path of a model, compiled once, and what of the model's paths is not computed
// (said loudly by the commands that use them).
#pragma once

#include <sinew/common/error.h>
#include <sinew/model/model_spec.h>
#include <sinew/paths/geometry_path.h>

#include <vector>

namespace sinew::paths {

/// The paths (GeometryPath and FunctionBasedPath) of a model's forces (muscles, path springs,
/// ligaments), in ForceSet order.
class PathSet {
 public:
  /// Throws sinew::Error (file, line, component) for a path that cannot be computed as written.
  /// `refinement`: which OpenSim's cylinder rule the paths follow (CylinderRefinement).
  explicit PathSet(const model::ModelSpec& spec,
                   CylinderRefinement refinement = CylinderRefinement::kSeveralWraps);

  const std::vector<GeometryPath>& paths() const { return paths_; }
  std::vector<GeometryPath>& mutable_paths() { return paths_; }

  /// What is left out, one Diagnostic each: paths of kinds not computed
  /// (Scholz2015GeometryPath: their owners have no path here) and PathWraps whose wrapping
  /// surface is not connected (those paths are computed straight past the wrap object).
  /// Computed when asked, so connecting surfaces shortens the list.
  Diagnostics ListOmissions(const model::ModelSpec& spec) const;

 private:
  std::vector<GeometryPath> paths_;
};

}  // namespace sinew::paths

// Builds the wrap surface of a model's wrap object (model::WrapObjectSpec) by its OpenSim type.
#pragma once

#include <sinew/model/model_spec.h>
#include <sinew/paths/wrap_surface.h>

#include <memory>
#include <string>
#include <vector>

namespace sinew::paths {

/// The surface of `spec` in its own frame W (spec.X_BW places W on the body). Reads OpenSim's
/// properties with OpenSim's defaults when absent (WrapSphere radius 0.05; WrapCylinder radius
/// 1, length 1) and its quadrant. Throws sinew::Error naming the object (file, line, name) for a
/// type Sinew does not wrap over, a dimension that is not one positive finite number, or an
/// unknown quadrant. `spec.active` is not looked at: the path skips inactive objects.
std::unique_ptr<WrapSurface> MakeWrapSurface(const model::WrapObjectSpec& spec);

/// Whether MakeWrapSurface builds objects of OpenSim type `type` (e.g. "WrapCylinder").
bool IsWrapSurfaceSupported(const std::string& type);

/// The OpenSim wrap object types MakeWrapSurface builds, sorted.
std::vector<std::string> SupportedWrapSurfaceTypes();

}  // namespace sinew::paths

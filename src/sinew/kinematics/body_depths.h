// Depth of each body in a model's joint tree: ground 0, its children 1, and so on.
#pragma once

#include <sinew/model/model_spec.h>

#include <vector>

namespace sinew::kinematics {

/// Number of joints between each body and ground (ground 0), joints taken in either
/// direction; a body no chain of joints reaches gets -1. Used to colour primitives by depth and
/// to assign collision families.
std::vector<int> CalcBodyDepths(const model::ModelSpec& spec);

}  // namespace sinew::kinematics

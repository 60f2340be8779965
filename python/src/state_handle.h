// StateHandle: what sinew.State holds, an engine::State with the model it belongs to (for
// names, and to place the bodies when coordinates are set).
#pragma once

#include <sinew/engine/state.h>

#include "model_handle.h"

namespace sinew::python {

struct StateHandle {
  ModelPtr model;
  engine::State state;
};

}  // namespace sinew::python

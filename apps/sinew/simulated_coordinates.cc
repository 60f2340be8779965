#include "apps/sinew/simulated_coordinates.h"

#include <sinew/common/error.h>
#include <sinew/engine/assemble.h>

namespace sinew::cli {

SimulatedCoordinates::SimulatedCoordinates(const model::ModelSpec& spec,
                                           const engine::System& system, const engine::State& state)
    : system_(system) {
  for (const model::CoordinateSpec& c : spec.coordinates) {
    names_.push_back(c.name);
    defaults_.push_back(c.default_value);
    bool found = true;
    try {
      engine::GetCoordinateValue(system, state, c.name);
    } catch (const Error&) {
      found = false;  // not simulated: its default stands
    }
    simulated_.push_back(found);
  }
}

std::vector<double> SimulatedCoordinates::Read(const engine::State& state) const {
  std::vector<double> q = defaults_;
  for (size_t i = 0; i < q.size(); ++i) {
    if (simulated_[i]) q[i] = engine::GetCoordinateValue(system_, state, names_[i]);
  }
  return q;
}

}  // namespace sinew::cli

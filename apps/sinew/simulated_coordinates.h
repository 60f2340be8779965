// The model's coordinates read off simulated states, for `simulate --export` to draw the
// muscle paths (which need coordinates as well as body poses).
#pragma once

#include <sinew/engine/state.h>
#include <sinew/engine/system.h>
#include <sinew/model/model_spec.h>

#include <vector>

namespace sinew::cli {

/// Reads ModelSpec::coordinates from engine states by name. A coordinate the system does not
/// simulate (its joint left out) keeps its default value.
class SimulatedCoordinates {
 public:
  /// `state` is any state of `system` (used to find which coordinates it has).
  SimulatedCoordinates(const model::ModelSpec& spec, const engine::System& system,
                       const engine::State& state);
  /// The coordinates at `state` (rad, m), in ModelSpec::coordinates order.
  std::vector<double> Read(const engine::State& state) const;

 private:
  const engine::System& system_;
  std::vector<std::string> names_;
  std::vector<bool> simulated_;
  std::vector<double> defaults_;
};

}  // namespace sinew::cli

// `sinew analyze`'s muscle tables (OpenSim MuscleAnalysis names): FiberLength, TendonLength,
// ActiveFiberForce, PassiveFiberForce and TendonForce of every simulated muscle whose
// activation and fiber_length columns the states file holds, from the path's length and
// lengthening speed at each row.
#pragma once

#include <sinew/engine/system.h>
#include <sinew/io/storage.h>
#include <sinew/model/model_spec.h>
#include <sinew/muscles/path_actuator.h>

#include <memory>
#include <string>
#include <vector>

namespace sinew::cli {

/// The muscle tables of one analysis.
class MuscleTables {
 public:
  /// Finds the muscles of `spec` that Sinew simulates and whose state variables `states`
  /// holds (labels "/forceset/<m>/activation" or "<m>.activation", and fiber_length). No
  /// table when there is none, or when the model cannot be built (a warning on stderr).
  MuscleTables(const model::ModelSpec& spec, const io::Storage& states,
               const std::vector<std::string>& path_names);

  bool empty() const { return muscles_.empty(); }
  /// The state-file labels the tables read.
  const std::vector<std::string>& used_labels() const { return used_labels_; }
  /// Appends row `r` of `states` at the paths' lengths and lengthening speeds (path order).
  void AppendRow(const io::Storage& states, int r, const std::vector<double>& lengths,
                 const std::vector<double>& speeds);
  /// Writes the five tables into `dir`.
  void Write(const std::string& dir) const;

 private:
  struct Muscle {
    const muscles::PathActuator* actuator;
    int path;                      // index into the paths' order
    int activation, fiber_length;  // columns of the states table
  };
  std::unique_ptr<engine::System> system_;
  std::vector<Muscle> muscles_;
  std::vector<io::Storage> tables_;  // FiberLength, TendonLength, Active, Passive, Tendon force
  std::vector<std::string> used_labels_;
};

}  // namespace sinew::cli

#include <sinew/common/error.h>
#include <sinew/io/storage_labels.h>
#include <sinew/opensim/initial_states.h>
#include <sinew/opensim/support.h>

#include <algorithm>

namespace sinew::opensim {

InitialStates ApplyInitialStates(io::Storage& storage, const std::string& storage_path,
                                 model::ModelSpec& spec, int row) {
  if (storage.NumRows() == 0) {
    throw Error({storage_path, 0}, "", "the initial-states file has no rows");
  }
  std::vector<std::string> rotational, simulated;
  for (const model::CoordinateSpec& c : spec.coordinates) {
    if (c.joint == model::kNone || !IsJointSimulated(spec.joints[c.joint])) continue;
    simulated.push_back(c.name);
    if (c.motion_type == model::MotionType::kRotational) rotational.push_back(c.name);
  }
  InitialStates result;
  result.t0 = storage.time[row];
  for (const std::string& label : storage.labels) {
    if (!io::ParseColumnLabel(label, simulated)) result.unused_labels.push_back(label);
  }
  io::ConvertDegreesToRadians(storage, rotational);
  for (model::CoordinateSpec& c : spec.coordinates) {
    const int value = io::FindCoordinateColumn(storage, c.name, io::CoordinateColumnKind::kValue);
    const int speed = io::FindCoordinateColumn(storage, c.name, io::CoordinateColumnKind::kSpeed);
    if (value >= 0) c.default_value = storage.Value(row, value);
    if (speed >= 0) c.default_speed_value = storage.Value(row, speed);
    const bool is_simulated =
        std::find(simulated.begin(), simulated.end(), c.name) != simulated.end();
    if (is_simulated && value < 0) result.missing.push_back(c.name + " (value)");
    if (is_simulated && speed < 0) result.missing.push_back(c.name + " (speed)");
  }
  return result;
}

}  // namespace sinew::opensim

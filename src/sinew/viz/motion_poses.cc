#include <sinew/kinematics/coordinate_couplers.h>
#include <sinew/kinematics/coordinate_motion.h>
#include <sinew/kinematics/forward_kinematics.h>
#include <sinew/kinematics/kinematic_tree.h>
#include <sinew/viz/motion_poses.h>

#include <algorithm>

namespace sinew::viz {
namespace {

// The coordinates a table row drives, over the model's defaults, with coupler-driven
// coordinates set from their drivers.
std::vector<double> RowCoordinates(const model::ModelSpec& spec,
                                   const kinematics::KinematicTree& tree,
                                   const kinematics::CoordinateCouplers& couplers,
                                   const kinematics::MotionColumnMap& map, const io::Storage& table,
                                   int row) {
  std::vector<double> q = tree.default_q();
  const auto first = table.values.begin() + static_cast<ptrdiff_t>(row) * table.NumColumns();
  const std::vector<double> values(first, first + table.NumColumns());
  kinematics::ApplyMotionRow(spec, map, values, table.in_degrees, q);
  couplers.Apply(q);
  return q;
}

std::vector<Transform> Poses(const kinematics::KinematicTree& tree, const std::vector<double>& q) {
  std::vector<Transform> X_GB(tree.num_bodies());
  kinematics::CalcBodyPoses(tree, q, X_GB);
  return X_GB;
}

kinematics::MotionColumnMap CheckedMap(const model::ModelSpec& spec, const io::Storage& table) {
  kinematics::MotionColumnMap map = kinematics::MapMotionColumns(spec, table.labels);
  if (std::none_of(map.coordinate.begin(), map.coordinate.end(),
                   [](int c) { return c != model::kNone; })) {
    throw Error("no column of the motion table names a coordinate of model '" + spec.name + "'");
  }
  return map;
}

// Appends to `notes` (when not null) the columns `map` could not use and the coordinates the
// table does not drive.
void NoteUnmatched(const model::ModelSpec& spec, const kinematics::MotionColumnMap& map,
                   const kinematics::CoordinateCouplers& couplers, Diagnostics* notes) {
  if (!notes) return;
  auto note = [notes](const std::string& component, const std::string& message) {
    Diagnostic d;
    d.component = component;
    d.message = message;
    notes->push_back(std::move(d));
  };
  for (const std::string& label : map.unknown) {
    note("", "column '" + label + "' names no coordinate; ignored");
  }
  for (int c : map.missing) {
    if (couplers.Drives(c)) continue;  // set from its coupler's drivers
    note(spec.coordinates[c].path, "not in the motion table; held at its default value");
  }
}

}  // namespace

BodyMotion DefaultPoseMotion(const model::ModelSpec& spec) {
  kinematics::KinematicTree tree(spec);
  BodyMotion motion;
  motion.times = {0.0};
  std::vector<double> q = tree.default_q();
  kinematics::CoordinateCouplers(spec).Apply(q);
  motion.X_GB = {Poses(tree, q)};
  motion.q = {std::move(q)};
  return motion;
}

BodyMotion MotionFromTable(const model::ModelSpec& spec, const io::Storage& table,
                           Diagnostics* notes) {
  kinematics::KinematicTree tree(spec);
  const kinematics::MotionColumnMap map = CheckedMap(spec, table);
  const kinematics::CoordinateCouplers couplers(spec);  // built once, applied to every row
  NoteUnmatched(spec, map, couplers, notes);
  BodyMotion motion;
  for (int row = 0; row < table.NumRows(); ++row) {
    if (row > 0 && !(table.time[row] > table.time[row - 1])) {
      throw Error("motion table times must increase (row " + std::to_string(row + 1) + ")");
    }
    motion.times.push_back(table.time[row]);
    motion.q.push_back(RowCoordinates(spec, tree, couplers, map, table, row));
    motion.X_GB.push_back(Poses(tree, motion.q.back()));
  }
  return motion;
}

BodyMotion MotionAtTime(const model::ModelSpec& spec, const io::Storage& table, double t,
                        Diagnostics* notes) {
  kinematics::KinematicTree tree(spec);
  const kinematics::MotionColumnMap map = CheckedMap(spec, table);
  const kinematics::CoordinateCouplers couplers(spec);  // built once, applied to every row
  NoteUnmatched(spec, map, couplers, notes);
  if (table.NumRows() == 0 || t < table.time.front() || t > table.time.back()) {
    throw Error("time " + std::to_string(t) + " s is outside the table's range");
  }
  // The row pair around t; coordinates blend linearly between them.
  const auto it = std::lower_bound(table.time.begin(), table.time.end(), t);
  const int hi = static_cast<int>(it - table.time.begin());
  const int lo = std::max(0, hi - 1);
  std::vector<double> q = RowCoordinates(spec, tree, couplers, map, table, hi);
  if (hi != lo && table.time[hi] > table.time[lo]) {
    const double s = (t - table.time[lo]) / (table.time[hi] - table.time[lo]);
    const std::vector<double> q0 = RowCoordinates(spec, tree, couplers, map, table, lo);
    for (size_t i = 0; i < q.size(); ++i) q[i] = q0[i] + s * (q[i] - q0[i]);
  }
  BodyMotion motion;
  motion.times = {t};
  motion.X_GB = {Poses(tree, q)};
  motion.q = {std::move(q)};
  return motion;
}

std::vector<Transform> PosesAtTime(const model::ModelSpec& spec, const io::Storage& table, double t,
                                   Diagnostics* notes) {
  return MotionAtTime(spec, table, t, notes).X_GB[0];
}

}  // namespace sinew::viz

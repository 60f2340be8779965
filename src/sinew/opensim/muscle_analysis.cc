#include <sinew/io/storage_functions.h>
#include <sinew/io/storage_labels.h>
#include <sinew/kinematics/coordinate_motion.h>
#include <sinew/kinematics/kinematic_tree.h>
#include <sinew/muscles/path_actuator.h>
#include <sinew/opensim/muscle_analysis.h>
#include <sinew/opensim/parser.h>
#include <sinew/paths/path_analysis.h>

#include <algorithm>
#include <limits>
#include <span>
#include <utility>

namespace sinew::opensim {
namespace {

// The column of a muscle's state variable: OpenSim 4's or OpenSim 3's label, or -1.
int FindStateColumn(const io::Storage& states, const std::string& muscle,
                    const std::string& variable) {
  const int c = states.FindColumn("/forceset/" + muscle + "/" + variable);
  return c >= 0 ? c : states.FindColumn(muscle + "." + variable);
}

// The coordinate speeds of the motion: the first derivative of OpenSim's spline through each
// coordinate column (GCVSplineSet of degree 5, as its AnalyzeTool differentiates a motion), in
// radians. Empty when the table has too few rows for that spline.
std::vector<functions::FunctionPtr> FitSpeedSplines(io::Storage motion,
                                                    const model::ModelSpec& spec) {
  std::vector<std::string> rotational;
  for (const model::CoordinateSpec& c : spec.coordinates) {
    if (c.motion_type == model::MotionType::kRotational) rotational.push_back(c.name);
  }
  io::ConvertDegreesToRadians(motion, rotational);
  constexpr int kHalfOrder = 3;
  if (motion.NumRows() < 2 * kHalfOrder) return {};
  return io::FitColumnSplines(motion, kHalfOrder);
}

io::Storage MakeTable(const std::string& name, const std::vector<std::string>& labels) {
  io::Storage table;
  table.name = name;
  table.labels = labels;
  return table;
}

}  // namespace

std::vector<int> ChooseMomentArmCoordinates(const model::ModelSpec& spec,
                                            const kinematics::CoordinateCouplers& couplers,
                                            const std::vector<std::string>& names) {
  std::vector<int> out;
  if (names.empty()) {
    for (size_t c = 0; c < spec.coordinates.size(); ++c) {
      if (!spec.coordinates[c].locked && !couplers.Drives(static_cast<int>(c))) {
        out.push_back(static_cast<int>(c));
      }
    }
    return out;
  }
  for (const std::string& name : names) {
    const int c = spec.FindCoordinate(name);
    if (c == model::kNone) throw Error("the model has no coordinate '" + name + "'");
    out.push_back(c);
  }
  return out;
}

struct MuscleAnalysis::Muscle {
  const muscles::PathActuator* actuator;
  int path;                      // index into the paths' order
  int activation, fiber_length;  // columns of the motion table
};

MuscleAnalysis::MuscleAnalysis(const model::ModelSpec& spec, const std::string& model_path,
                               paths::CylinderRefinement refinement, const io::Storage& motion,
                               const std::string& motion_path, Diagnostics* notes)
    : spec_(spec), motion_(motion), motion_path_(motion_path), paths_(spec, refinement) {
  if (paths_.paths().empty()) {
    throw Error({model_path, 0}, "", "the model has no geometry path to analyze");
  }
  std::vector<std::string> path_names;
  for (const paths::GeometryPath& path : paths_.paths()) path_names.push_back(path.name());
  const auto has_states = [&](const std::string& name) {
    return FindStateColumn(motion, name, "activation") >= 0 &&
           FindStateColumn(motion, name, "fiber_length") >= 0;
  };
  if (std::none_of(path_names.begin(), path_names.end(), has_states)) return;
  OpenSimParser parser;
  try {
    system_ = std::make_unique<engine::System>(spec.gravity);
    parser.ParseSpec(*system_, spec);
    system_->Finalize();
  } catch (const Error& error) {
    system_.reset();
    if (notes) {
      Diagnostic note;
      note.where.file = model_path;
      note.message =
          std::string("no muscle tables: the model cannot be built (") + error.what() + ")";
      notes->push_back(std::move(note));
    }
    return;
  }
  for (const auto& element : system_->force_elements()) {
    const auto* actuator = dynamic_cast<const muscles::PathActuator*>(element.get());
    if (!actuator || actuator->StateVariableNames().empty()) continue;
    const auto path = std::find(path_names.begin(), path_names.end(), actuator->name());
    const int activation = FindStateColumn(motion, actuator->name(), "activation");
    const int fiber = FindStateColumn(motion, actuator->name(), "fiber_length");
    if (path == path_names.end() || activation < 0 || fiber < 0) continue;
    muscles_.push_back({actuator, static_cast<int>(path - path_names.begin()), activation, fiber});
    muscle_state_labels_.push_back(motion.labels[activation]);
    muscle_state_labels_.push_back(motion.labels[fiber]);
  }
}

MuscleAnalysis::~MuscleAnalysis() = default;

MuscleAnalysisTables MuscleAnalysis::Run(const std::vector<int>& coordinates,
                                         Diagnostics* notes) const {
  const io::Storage& motion = motion_;
  if (motion.NumRows() == 0) throw Error({motion_path_, 0}, "", "the motion has no rows");
  const kinematics::KinematicTree tree(spec_);
  const kinematics::CoordinateCouplers couplers(spec_);
  const kinematics::MotionColumnMap map = kinematics::MapMotionColumns(spec_, motion.labels);
  const std::vector<functions::FunctionPtr> splines = FitSpeedSplines(motion, spec_);
  if (splines.empty() && notes) {
    Diagnostic note;
    note.where.file = motion_path_;
    note.message = "the table has " + std::to_string(motion.NumRows()) +
                   " rows, fewer than the 6 a quintic spline needs: lengthening speeds are "
                   "written as NaN";
    notes->push_back(std::move(note));
  }
  std::vector<std::string> path_names;
  for (const paths::GeometryPath& path : paths_.paths()) path_names.push_back(path.name());
  MuscleAnalysisTables out;
  out.length = MakeTable("Length", path_names);
  out.lengthening_speed = MakeTable("LengtheningSpeed", path_names);
  for (int c : coordinates)
    out.moment_arms.push_back(MakeTable("MomentArm_" + spec_.coordinates[c].name, path_names));
  std::vector<std::string> muscle_names;
  for (const Muscle& m : muscles_) muscle_names.push_back(m.actuator->name());
  if (!muscles_.empty()) {
    for (const char* name :
         {"FiberLength", "TendonLength", "ActiveFiberForce", "PassiveFiberForce", "TendonForce"})
      out.muscles.push_back(MakeTable(name, muscle_names));
  }

  const size_t num_paths = path_names.size();
  const std::vector<double> no_speeds(num_paths, std::numeric_limits<double>::quiet_NaN());
  paths::PathAnalysis analysis(spec_, tree, couplers, paths_, coordinates);
  std::vector<double> q = tree.default_q();
  std::vector<double> u(q.size());
  const size_t num_columns = motion.labels.size();
  std::vector<double> row(num_paths);
  std::vector<std::vector<double>> muscle_rows(out.muscles.size());
  VecX z(2);
  for (int r = 0; r < motion.NumRows(); ++r) {
    const double t = motion.time[r];
    kinematics::ApplyMotionRow(
        spec_, map, std::span<const double>(motion.values.data() + r * num_columns, num_columns),
        motion.in_degrees, q);
    std::fill(u.begin(), u.end(), 0.0);
    for (size_t k = 0; k < num_columns && !splines.empty(); ++k) {
      if (map.coordinate[k] != model::kNone)
        u[map.coordinate[k]] = splines[k]->CalcDerivative(t, 1);
    }
    couplers.Apply(q);
    couplers.ApplySpeeds(q, u);
    analysis.Calc(q, u);
    const std::vector<double>& speeds = splines.empty() ? no_speeds : analysis.lengthening_speeds();
    out.length.AppendRow(t, analysis.lengths());
    out.lengthening_speed.AppendRow(t, speeds);
    for (size_t k = 0; k < coordinates.size(); ++k) {
      for (size_t p = 0; p < num_paths; ++p) row[p] = analysis.opensim_moment_arm(k, p);
      out.moment_arms[k].AppendRow(t, row);
    }
    for (std::vector<double>& muscle_row : muscle_rows) muscle_row.clear();
    for (const Muscle& m : muscles_) {
      z << motion.Value(r, m.activation), motion.Value(r, m.fiber_length);
      // The excitation does not enter a muscle's forces, only its activation's rate.
      const muscles::MuscleQuantities quantities =
          m.actuator->model().Calc(z, 0.0, {analysis.lengths()[m.path], speeds[m.path]});
      muscle_rows[0].push_back(quantities.fiber_length);
      muscle_rows[1].push_back(quantities.tendon_length);
      muscle_rows[2].push_back(quantities.active_fiber_force);
      muscle_rows[3].push_back(quantities.passive_fiber_force);
      muscle_rows[4].push_back(quantities.tendon_force);
    }
    for (size_t k = 0; k < out.muscles.size(); ++k) out.muscles[k].AppendRow(t, muscle_rows[k]);
  }
  return out;
}

}  // namespace sinew::opensim

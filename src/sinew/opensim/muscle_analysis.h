// OpenSim MuscleAnalysis-style tables of a model's geometry paths (muscles, path springs,
// ligaments) over a motion: what `sinew analyze` writes and Python's Model.analyze returns.
// Length and LengtheningSpeed of every path, MomentArm_<coordinate> for the chosen coordinates
// (OpenSim's moment arms, PathAnalysis::opensim_moment_arm), and, when the table is a states
// table holding muscles' activation and fiber_length, FiberLength, TendonLength,
// ActiveFiberForce, PassiveFiberForce and TendonForce of those muscles.
#pragma once

#include <sinew/common/error.h>
#include <sinew/engine/system.h>
#include <sinew/io/storage.h>
#include <sinew/kinematics/coordinate_couplers.h>
#include <sinew/model/model_spec.h>
#include <sinew/paths/path_set.h>

#include <memory>
#include <string>
#include <vector>

namespace sinew::opensim {

/// The coordinates to give moment arms about: those named in `names` (sinew::Error naming the
/// first the model does not have), or, when `names` is empty, every coordinate that can move
/// on its own (not locked, not set by a coupler).
std::vector<int> ChooseMomentArmCoordinates(const model::ModelSpec& spec,
                                            const kinematics::CoordinateCouplers& couplers,
                                            const std::vector<std::string>& names);

/// The tables of one analysis, each labelled by path (or muscle) name over the motion's times.
struct MuscleAnalysisTables {
  io::Storage length;             ///< "Length", m
  io::Storage lengthening_speed;  ///< "LengtheningSpeed", m/s (NaN when the motion is too short)
  std::vector<io::Storage> moment_arms;  ///< "MomentArm_<coordinate>", m, in coordinate order
  /// FiberLength, TendonLength (m), ActiveFiberForce, PassiveFiberForce, TendonForce (N); empty
  /// when the table holds no simulated muscle's activation and fiber_length.
  std::vector<io::Storage> muscles;
};

/// One model's paths over one motion or states table.
class MuscleAnalysis {
 public:
  /// Builds the paths of `spec` (sinew::Error when it has none) and finds the muscles whose
  /// activation and fiber_length `motion` holds ("/forceset/<m>/activation" or
  /// "<m>.activation"); their tables need the model built: one that cannot be built gives none,
  /// and a note in `notes`. `model_path` and `motion_path` name the files in errors and notes.
  /// `spec` and `motion` must outlive the analysis.
  MuscleAnalysis(const model::ModelSpec& spec, const std::string& model_path,
                 paths::CylinderRefinement refinement, const io::Storage& motion,
                 const std::string& motion_path, Diagnostics* notes);
  ~MuscleAnalysis();
  MuscleAnalysis(const MuscleAnalysis&) = delete;
  MuscleAnalysis& operator=(const MuscleAnalysis&) = delete;

  const paths::PathSet& paths() const { return paths_; }
  /// The motion's labels the muscle tables read, so that a caller reporting unused columns can
  /// leave them out.
  const std::vector<std::string>& muscle_state_labels() const { return muscle_state_labels_; }

  /// The tables over every row of the motion, moment arms about `coordinates` (indices into
  /// spec.coordinates, ChooseMomentArmCoordinates). Coordinate columns are mapped by name
  /// (kinematics::MapMotionColumns; degrees converted when the table says so), coupled
  /// coordinates follow their drivers, and coordinates without a column keep their defaults.
  /// Coordinate speeds are the first derivative of OpenSim's quintic spline through each
  /// coordinate column (as its AnalyzeTool differentiates a motion); with fewer than 6 rows
  /// there is none, the lengthening speeds (and the muscles' velocity-dependent forces) take
  /// NaN speeds and `notes` says so. Throws sinew::Error for a table without rows.
  MuscleAnalysisTables Run(const std::vector<int>& coordinates, Diagnostics* notes) const;

 private:
  struct Muscle;
  const model::ModelSpec& spec_;
  const io::Storage& motion_;
  std::string motion_path_;
  paths::PathSet paths_;
  std::unique_ptr<engine::System> system_;  // the muscles' models, when any is tabulated
  std::vector<Muscle> muscles_;
  std::vector<std::string> muscle_state_labels_;
};

}  // namespace sinew::opensim

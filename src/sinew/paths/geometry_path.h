// A muscle's, spring's or ligament's GeometryPath compiled from the spec, and the path it takes
// at a pose: the active points in order (wrap tangent points included once a wrapping surface
// is connected), the straight segments' unit directions and the length.
#pragma once

#include <sinew/math/transform.h>
#include <sinew/model/model_spec.h>
#include <sinew/paths/path_point.h>
#include <sinew/paths/wrap_surface.h>

#include <array>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace sinew::paths {

/// One of a path's PathWrap entries: a wrap object and the points it may act between.
struct PathWrap {
  std::string wrap_object;  ///< The WrapObject's name.
  std::string type;         ///< Its class (WrapCylinder, WrapEllipsoid, ...).
  int body = model::kGroundIndex;
  Transform X_BW;  ///< The wrap object's frame W in its body.
  bool active = true;
  /// The path points (0-based, inclusive; indices into GeometryPath::points()) between whose
  /// active points the object may wrap; OpenSim's 1-based `range`, -1 meaning the first / last.
  int first_point = 0, last_point = 0;
  WrapOptions options;
  /// A wrap object on two frames (WrapDoubleCylinderObst): the body of its second frame V and
  /// V's pose in that body; kNone for every other object.
  int second_body = model::kNone;
  Transform X_BV;
  /// The surface that wraps; null until one is connected, and the path then stays straight.
  std::shared_ptr<const WrapSurface> surface;
};

/// Where one point of the current path is at a pose.
struct PathPointState {
  int point = model::kNone;  ///< Index into GeometryPath::points(); kNone for a tangent point.
  int wrap = model::kNone;   ///< For tangent points: index into GeometryPath::wraps().
  /// For tangent points: which of the wrap's (0 T1, 1 T2, 2 T3, 3 T4: WrapResult's points).
  int tangent = 0;
  int body = model::kGroundIndex;
  Vec3 p_BP = Vec3::Zero();  ///< In the body frame (m).
  Vec3 p_GP = Vec3::Zero();  ///< In ground (m).
  /// Tangent points: where the last wrapping pass put the point, in the body frame (m). Equal to
  /// p_BP except for a stale tangent point (PathState::stale_tangent_points), whose p_BP is
  /// where OpenSim first read it; OpenSim applies the point's forces here (docs/paths.md).
  Vec3 p_BP_placed = Vec3::Zero();
  /// Moving points: dp_BP/dq for the coordinate of each location component (kNone: none).
  std::array<int, 3> coordinates{model::kNone, model::kNone, model::kNone};
  std::array<Vec3, 3> dp_BP_dq{Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  /// First tangent point of a wrap: the length of the path over the surface to the next point
  /// (the second tangent point) in m; negative for every other point.
  double arc_length_to_next = -1.0;
};

/// dL/dq of a FunctionBasedPath about one coordinate it depends on.
struct LengthSlope {
  int coordinate = model::kNone;  ///< Index into ModelSpec::coordinates.
  double dL_dq = 0.0;             ///< m per rad or m per m: minus OpenSim's moment arm.
};

/// What wrapping one object over its range gave (OpenSim's WrapAction, for its reordering).
enum class WrapOutcome { kNoWrap, kPointInside, kWrapped };

/// OpenSim caches a point's location in ground the first time it is read in an evaluation;
/// moving a tangent point in a later pass does not refresh that cache, so the path's straight
/// segments (its length) keep the location first read, while the surfaces wrap the point where
/// it is now (docs/paths.md). Per wrap, for T1 and T2: whether read, the location read (in the
/// body and in ground), and where the point is now.
struct TangentPointReads {
  /// Forgets every read, for `num_wraps` wraps (keeps the buffers).
  void Reset(int num_wraps);
  /// Reads `point`: the first read of a tangent point keeps its location, later reads give it.
  void Read(PathPointState& point);
  /// A tangent point just placed: remembers where it is (also in its p_BP_placed), and takes
  /// the location read, if any.
  void Place(PathPointState& point);
  /// Where a path point is now (for the surfaces), in ground.
  Vec3 CurrentLocation(const PathPointState& point) const;
  std::vector<std::array<bool, 4>> read;
  std::vector<std::array<Vec3, 4>> p_BP_read, p_GP_read, p_GP_current;
};

/// The bookkeeping of GeometryPath's wrapping passes, kept with the PathState so that a path
/// evaluated again reuses its buffers (no heap use once they are sized).
struct WrapPasses {
  std::vector<int> order;  ///< the wraps in the order they are applied
  std::vector<WrapOutcome> outcomes;
  TangentPointReads reads;
};

/// A path at one pose. Segment i joins points[i] and points[i + 1].
struct PathState {
  std::vector<PathPointState> points;
  /// Per segment: the unit vector from points[i] to points[i + 1] in ground; zero for a segment
  /// over a wrap surface (T1 to T2), NaN when the two points coincide (as OpenSim).
  std::vector<Vec3> e_G;
  /// Per segment: its length (m); the arc length for a segment over a wrap surface.
  std::vector<double> segment_length;
  double length = 0.0;  ///< Sum of segment lengths (m).
  /// Filled only when CalcState is asked for arc points: per arc, the points along it over the
  /// surface, in ground (m), for drawing; empty for an arc the path does not take at this pose.
  /// Wrap w (index into GeometryPath::wraps()) has two: arc_G[ArcIndex(w, 0)] from T1 to T2
  /// inclusive, and arc_G[ArcIndex(w, 1)] from T3 to T4 inclusive (WrapDoubleCylinderObst's
  /// second cylinder only).
  std::vector<std::vector<Vec3>> arc_G;
  /// The arc_G index of wrap w's arc starting at tangent point `tangent` (0 or 1: T1 to T2;
  /// 2 or 3: T3 to T4).
  static int ArcIndex(int w, int tangent) { return 2 * w + (tangent >= 2 ? 1 : 0); }
  /// Tangent points that stand where an earlier wrapping pass put them, not where the last
  /// pass did: OpenSim's length keeps a point's first location in ground (docs/paths.md), and
  /// Sinew reproduces it. Zero for a path with one wrap object.
  int stale_tangent_points = 0;
  /// FunctionBasedPath (no points, segments or arcs): per coordinate of its coordinate_paths,
  /// in that order, dL/dq (minus its moment arm function when the file gives them). Empty for
  /// a GeometryPath.
  std::vector<LengthSlope> slopes;
  /// FunctionBasedPath with a lengthening_speed_function: that function, and its arguments
  /// (q, then u, of its coordinates) with q filled by CalcState and u by CalcLengtheningSpeed.
  /// Null for every other path.
  const functions::Function* speed_function = nullptr;
  mutable std::vector<double> speed_arguments;
  /// Scratch of the wrapping passes (GeometryPath::CalcState's own).
  WrapPasses wrap_passes;
};

/// When and how OpenSim's WrapCylinder refines its tangent points toward tangency with the
/// helix (docs/wrapping.md). OpenSim 4.4 stopped refining on a path with a single wrap object (a
/// speed-up, opensim-core pull request 3125, February 2022); every earlier OpenSim (2.x, 3.x,
/// 4.0 to 4.3) refines on every path. Results written by those versions, such as OpenSim's
/// std_arm26_states.sto, need kAlways (docs/forward.md). OpenSim 4.4.1 (May 2023) changed
/// which helix sample the second tangent point is checked against (WrapOptions::
/// t2_checked_after_t1_moves); results of OpenSim 4.4.0, such as MyoConverter's reference
/// moment arms, need kSeveralWrapsOpenSim44.
enum class CylinderRefinement {
  kSeveralWraps,           ///< OpenSim 4.4.1 and later: only on paths with two or more wrap objects
  kSeveralWrapsOpenSim44,  ///< OpenSim 4.4.0: the same paths, T2 checked as before 4.4.1
  kAlways,                 ///< OpenSim before 4.4: on every path, T2 checked as before 4.4.1
};

/// The rule named `name`, as `--cylinder-refinement` and Python's `cylinder_refinement` take
/// it: "several-wraps" (kSeveralWraps), "opensim-4.4" (kSeveralWrapsOpenSim44) or "always"
/// (kAlways); nullopt for any other name.
std::optional<CylinderRefinement> FindCylinderRefinement(const std::string& name);

/// With several wrap objects, OpenSim repeats its wrapping passes at most this many times...
inline constexpr int kMaxWrapPasses = 8;
/// ... until the path length changes by less than this between passes (m).
inline constexpr double kWrapPassTolerance = 0.0005;

/// A force's path: a GeometryPath (points, wraps) or a FunctionBasedPath (a length function of
/// coordinates; function_path() non-null, points() and wraps() empty). Immutable once built,
/// apart from connecting wrap surfaces before use.
class GeometryPath {
 public:
  /// Compiles the path of `owner` (a force with a geometry_path or a function_based_path) and
  /// connects the wrap surface
  /// of every PathWrap whose wrap object is of a type MakeWrapSurface builds (the others stay
  /// unconnected: the path goes straight past them, and PathSet::ListOmissions names them).
  /// Throws sinew::Error (file, line, component) for a path with fewer than two points, a
  /// PathWrap whose range names points the path does not have, or a supported wrap object with
  /// bad dimensions. `refinement` says which OpenSim's cylinder rule to follow.
  GeometryPath(const model::ModelSpec& spec, const model::ForceSpec& owner,
               CylinderRefinement refinement = CylinderRefinement::kSeveralWraps);

  /// The owner's name (the muscle, spring or ligament), used as the label in tables.
  const std::string& name() const { return name_; }
  /// The owner's component path, e.g. "/forceset/soleus_r".
  const std::string& component() const { return component_; }
  const SourceLocation& where() const { return where_; }
  const std::vector<PathPoint>& points() const { return points_; }
  const std::vector<PathWrap>& wraps() const { return wraps_; }
  /// The FunctionBasedPath, or null for a GeometryPath.
  const model::FunctionBasedPathSpec* function_path() const {
    return function_path_ ? &*function_path_ : nullptr;
  }

  /// Connects (or, with nullptr, disconnects) the surface that implements wrap `wrap` (index
  /// into wraps()), replacing the one the constructor connected.
  void ConnectWrapSurface(int wrap, std::shared_ptr<const WrapSurface> surface);

  /// The path at coordinates q (ModelSpec::coordinates order) with body poses X_GB (from
  /// kinematics::CalcBodyPoses at the same q), wrapped over its connected surfaces as OpenSim's
  /// GeometryPath::applyWrapObjects does (docs/paths.md). Reuses `state`'s buffers. Throws
  /// sinew::Error naming the path when fewer than two of its points are active. With
  /// `with_arc_points`, also fills PathState::arc_G (sampling arcs costs more than wrapping).
  /// A FunctionBasedPath fills only the length, PathState::slopes and the speed function.
  void CalcState(std::span<const double> q, std::span<const Transform> X_GB, PathState& state,
                 bool with_arc_points = false) const;

 private:
  // True when it leaves the segments (CalcSegments) of the path it leaves; false when it
  // stops before (no wrap objects, or a range without active points).
  bool ApplyWraps(std::span<const double> q, std::span<const Transform> X_GB, PathState& state,
                  bool with_arc_points) const;
  bool ApplyWrap(int wrap, std::span<const double> q, std::span<const Transform> X_GB,
                 PathState& state, WrapOutcome& outcome, TangentPointReads& reads,
                 bool with_arc_points) const;
  static void RemoveTangentPoints(int wrap, PathState& state);
  // Empties wrap's arcs in state.arc_G (when arc points are asked for).
  static void ClearArcs(int wrap, PathState& state);
  static void CalcSegments(PathState& state);
  void CalcFunctionState(std::span<const double> q, PathState& state) const;

  std::string name_, component_;
  SourceLocation where_;
  std::vector<PathPoint> points_;
  std::vector<PathWrap> wraps_;
  CylinderRefinement refinement_;
  std::optional<model::FunctionBasedPathSpec> function_path_;
};

}  // namespace sinew::paths

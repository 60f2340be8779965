// Muscles, path springs and ligaments for drawing: every GeometryPath of a model as a polyline
// in ground through its active points, wrap tangent points and the points along its wrapped
// arcs, frame by frame.
#pragma once

#include <sinew/common/error.h>
#include <sinew/io/storage.h>
#include <sinew/math/transform.h>
#include <sinew/model/model_spec.h>
#include <sinew/viz/body_motion.h>

#include <string>
#include <vector>

namespace sinew::viz {

/// The polylines of a model's paths over a motion.
struct PathLines {
  /// The owners' component paths ("/forceset/biceps"), in ForceSet order.
  std::vector<std::string> names;
  /// vertices[k][i]: path i's polyline at frame k, in ground (m). A path with fewer than two
  /// active points at a frame has no vertices there.
  std::vector<std::vector<std::vector<Vec3>>> vertices;
  Vec3 color = Vec3(0.8, 0.1, 0.1);  ///< RGB in [0, 1]: muscle red.
  /// activation[k][i]: path i's activation at frame k, in [0, 1], when ShadeByActivation found
  /// it (NaN for a path the table has no activation for); empty otherwise.
  std::vector<std::vector<double>> activation;
};

/// The colour a path is drawn in: muscle red without an activation (NaN), else from
/// kInactiveColor (activation 0) to PathLines::color (activation 1), linearly.
Vec3 PathColor(const PathLines& lines, double activation);
/// The colour of a path at activation 0 (blue, as OpenSim's viewer shades inactive muscles).
inline Vec3 InactiveColor() { return Vec3(0.15, 0.2, 0.75); }

/// The polyline of one path state: its points in order (paths::PathState::points[i].p_GP),
/// with the interior points of each wrapped arc (PathState::arc_G) between its two tangent
/// points. Declared here for the tests; `arc_G` may be empty (no arcs drawn).
std::vector<Vec3> PathPolyline(const std::vector<Vec3>& p_GP, const std::vector<int>& arc_of,
                               const std::vector<std::vector<Vec3>>& arc_G);

/// The paths of `spec` at every frame of `motion`, wrapped over their connected surfaces as
/// paths::GeometryPath::CalcState does, with arc points. Needs motion.q (one coordinate vector
/// per frame); without it, or for a model without paths, gives no paths. A path that cannot
/// be computed at a frame (fewer than two active points), or at all, is left out there with
/// one warning per path in `warnings` (when not null); so are FunctionBasedPaths (they have no
/// points to draw), with one warning naming them all.
PathLines CalcPathLines(const model::ModelSpec& spec, const BodyMotion& motion,
                        Diagnostics* warnings);

/// Fills lines.activation from the columns of `table` that hold a path owner's activation
/// (OpenSim 4 "/forceset/NAME/activation" or older "NAME.activation"), at each of `times` (s;
/// one per frame of `lines`), interpolated linearly between rows and clamped to [0, 1].
/// Returns how many paths have an activation column; with none, lines.activation stays empty.
int ShadeByActivation(const io::Storage& table, const std::vector<double>& times, PathLines& lines);

}  // namespace sinew::viz

// One point of a muscle's or ligament's GeometryPath, compiled from the spec, and where it is
// at a pose: OpenSim's PathPoint (fixed in its body), ConditionalPathPoint (fixed, but part of
// the path only while one coordinate is inside a range) and MovingPathPoint (its x, y, z in its
// frame are functions of coordinates).
#pragma once

#include <sinew/functions/function.h>
#include <sinew/math/transform.h>
#include <sinew/model/model_spec.h>

#include <array>
#include <span>
#include <string>

namespace sinew::paths {

/// OpenSim's path point classes.
enum class PathPointKind { kFixed, kConditional, kMoving };

/// How far outside its range a ConditionalPathPoint's coordinate may be and the point still
/// count as active: OpenSim's ConditionalPathPoint::isActive compares with a 1e-5 margin.
inline constexpr double kConditionalRangeTolerance = 1e-5;

/// A path point of a model, ready to evaluate. Immutable.
struct PathPoint {
  std::string name;
  PathPointKind kind = PathPointKind::kFixed;
  int body = model::kGroundIndex;  ///< Index into ModelSpec::bodies.
  Vec3 p_BP = Vec3::Zero();        ///< Fixed and conditional points: location in the body.
  /// Conditional points: active when range_min - 1e-5 <= q[coordinate] <= range_max + 1e-5.
  int coordinate = model::kNone;
  double range_min = 0.0, range_max = 0.0;
  /// Moving points: p_FP[i] = functions[i](clamp(q[coordinates[i]], clamp_min[i],
  /// clamp_max[i])), or functions[i](0) without a coordinate; F is fixed on the body (X_BF).
  std::array<functions::FunctionPtr, 3> functions;
  std::array<int, 3> coordinates{model::kNone, model::kNone, model::kNone};
  std::array<double, 3> clamp_min{}, clamp_max{};
  Transform X_BF;

  /// Compiles a spec point of the path `path_component` (whose owner is at `where` in the
  /// file); `spec` gives the coordinates' ranges (OpenSim clamps a moving point's coordinate
  /// to its range). Throws sinew::Error (file, line, point) for a moving point without a
  /// function.
  static PathPoint FromSpec(const model::ModelSpec& spec, const model::PathPointSpec& point,
                            const SourceLocation& where, const std::string& path_component);

  /// Whether the point is part of the path at coordinates q (always, unless conditional).
  bool IsActive(std::span<const double> q) const;

  /// The point's location in its body at q (m).
  Vec3 CalcLocationInBody(std::span<const double> q) const;

  /// dp_BP/dq for each of the (up to three) coordinates in `coordinates` (zero vectors for the
  /// others and for fixed points), in the body frame (m per rad or m per m). As OpenSim's
  /// MovingPathPoint::getdPointdQ, the derivative is taken at the coordinate's value even
  /// outside its range, where the location itself stays clamped.
  std::array<Vec3, 3> CalcLocationDerivatives(std::span<const double> q) const;
};

}  // namespace sinew::paths

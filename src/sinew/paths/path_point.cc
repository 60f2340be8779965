#include <sinew/common/error.h>
#include <sinew/paths/path_point.h>

#include <algorithm>

namespace sinew::paths {

PathPoint PathPoint::FromSpec(const model::ModelSpec& spec, const model::PathPointSpec& point,
                              const SourceLocation& where, const std::string& path_component) {
  PathPoint out;
  out.name = point.name;
  out.body = point.body;
  out.p_BP = point.location;
  out.X_BF = point.X_BF;
  if (point.type == "ConditionalPathPoint") {
    out.kind = PathPointKind::kConditional;
    out.coordinate = point.coordinate;
    out.range_min = point.range_min;
    out.range_max = point.range_max;
  } else if (point.type == "MovingPathPoint") {
    out.kind = PathPointKind::kMoving;
    for (int i = 0; i < 3; ++i) {
      if (!point.location_functions[i]) {
        throw Error(
            where, path_component + "/" + point.name,
            "MovingPathPoint has no function for its location component " + std::to_string(i));
      }
      out.functions[i] = point.location_functions[i];
      out.coordinates[i] = point.location_coordinates[i];
      if (out.coordinates[i] != model::kNone) {
        const model::CoordinateSpec& c = spec.coordinates[out.coordinates[i]];
        out.clamp_min[i] = c.range_min;
        out.clamp_max[i] = c.range_max;
      }
    }
  }
  return out;
}

bool PathPoint::IsActive(std::span<const double> q) const {
  if (kind != PathPointKind::kConditional) return true;
  if (coordinate == model::kNone) return false;  // OpenSim: no coordinate, never active
  const double value = q[coordinate];
  return value >= range_min - kConditionalRangeTolerance &&
         value <= range_max + kConditionalRangeTolerance;
}

Vec3 PathPoint::CalcLocationInBody(std::span<const double> q) const {
  if (kind != PathPointKind::kMoving) return p_BP;
  Vec3 p_FP;
  for (int i = 0; i < 3; ++i) {
    const int c = coordinates[i];
    const double x = c == model::kNone ? 0.0 : std::clamp(q[c], clamp_min[i], clamp_max[i]);
    p_FP[i] = functions[i]->Calc(x);
  }
  return X_BF * p_FP;
}

std::array<Vec3, 3> PathPoint::CalcLocationDerivatives(std::span<const double> q) const {
  std::array<Vec3, 3> dp_BP{Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  if (kind != PathPointKind::kMoving) return dp_BP;
  for (int i = 0; i < 3; ++i) {
    const int c = coordinates[i];
    if (c == model::kNone) continue;
    dp_BP[i] = X_BF.R.col(i) * functions[i]->CalcDerivative(q[c], 1);
  }
  return dp_BP;
}

}  // namespace sinew::paths

#include <sinew/common/error.h>
#include <sinew/paths/geometry_path.h>
#include <sinew/paths/wrap_surface_factory.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace sinew::paths {
namespace {

WrapOptions::Method ParseMethod(const std::string& method) {
  if (method == "midpoint") return WrapOptions::Method::kMidpoint;
  if (method == "axial") return WrapOptions::Method::kAxial;
  return WrapOptions::Method::kHybrid;
}

// The wrap object named `name` on any body of the model, or nullptr.
const model::WrapObjectSpec* FindWrapObject(const model::ModelSpec& spec, const std::string& name,
                                            int* body) {
  for (size_t b = 0; b < spec.bodies.size(); ++b) {
    for (const model::WrapObjectSpec& w : spec.bodies[b].wrap_objects) {
      if (w.name == name) {
        *body = static_cast<int>(b);
        return &w;
      }
    }
  }
  return nullptr;
}

}  // namespace

std::optional<CylinderRefinement> FindCylinderRefinement(const std::string& name) {
  if (name == "several-wraps") return CylinderRefinement::kSeveralWraps;
  if (name == "opensim-4.4") return CylinderRefinement::kSeveralWrapsOpenSim44;
  if (name == "always") return CylinderRefinement::kAlways;
  return std::nullopt;
}

GeometryPath::GeometryPath(const model::ModelSpec& spec, const model::ForceSpec& owner,
                           CylinderRefinement refinement)
    : name_(owner.name), component_(owner.path), where_(owner.where), refinement_(refinement) {
  if (!owner.geometry_path && owner.function_based_path) {
    function_path_ = owner.function_based_path;
    const size_t n = function_path_->coordinates.size();
    if (!function_path_->length_function || n == 0 ||
        (!function_path_->moment_arm_functions.empty() &&
         function_path_->moment_arm_functions.size() != n)) {
      throw Error(where_, component_, "malformed FunctionBasedPath");
    }
    return;
  }
  if (!owner.geometry_path) {
    throw Error(where_, component_, "has no GeometryPath or FunctionBasedPath");
  }
  const model::GeometryPathSpec& path = owner.geometry_path.value();
  if (path.points.size() < 2) {
    throw Error(where_, component_,
                "a path needs at least two points; it has " + std::to_string(path.points.size()));
  }
  for (const model::PathPointSpec& point : path.points) {
    points_.push_back(PathPoint::FromSpec(spec, point, where_, component_));
  }
  const int num_points = static_cast<int>(points_.size());
  for (const model::PathWrapSpec& w : path.wraps) {
    PathWrap wrap;
    wrap.wrap_object = w.wrap_object;
    const model::WrapObjectSpec* object = FindWrapObject(spec, w.wrap_object, &wrap.body);
    if (!object) {
      throw Error(where_, component_, "wrap object '" + w.wrap_object + "' does not exist");
    }
    wrap.type = object->type;
    wrap.X_BW = object->X_BW;
    wrap.active = object->active;
    wrap.options.method = ParseMethod(w.method);
    wrap.second_body = object->second_body;
    wrap.X_BV = object->X_BV;
    // OpenSim: 1-based point numbers; anything below 1 means the first (last) point.
    wrap.first_point = w.range[0] < 1 ? 0 : w.range[0] - 1;
    wrap.last_point = w.range[1] < 1 ? num_points - 1 : w.range[1] - 1;
    if (wrap.first_point >= num_points || wrap.last_point >= num_points ||
        wrap.first_point > wrap.last_point) {
      throw Error(where_, component_,
                  "PathWrap over '" + w.wrap_object + "' has range " + std::to_string(w.range[0]) +
                      " " + std::to_string(w.range[1]) + " but the path has " +
                      std::to_string(num_points) + " points");
    }
    // Every shape Sinew wraps over is connected here, so every user of the path gets it; the
    // others stay unconnected and PathSet::ListOmissions names them.
    if (IsWrapSurfaceSupported(object->type)) wrap.surface = MakeWrapSurface(*object);
    wraps_.push_back(std::move(wrap));
  }
}

void GeometryPath::ConnectWrapSurface(int wrap, std::shared_ptr<const WrapSurface> surface) {
  wraps_.at(static_cast<size_t>(wrap)).surface = std::move(surface);
}

// OpenSim's FunctionBasedPath: L = f(q) of its coordinates; dL/dq_i = -r_i, with r_i its
// moment arm function when given, else -df/dq_i (exact partial derivatives).
void GeometryPath::CalcFunctionState(std::span<const double> q, PathState& state) const {
  const model::FunctionBasedPathSpec& f = *function_path_;
  const size_t n = f.coordinates.size();
  state.speed_arguments.resize(2 * n);
  for (size_t i = 0; i < n; ++i) state.speed_arguments[i] = q[f.coordinates[i]];
  const std::span<const double> x(state.speed_arguments.data(), n);
  state.length = f.length_function->CalcN(x);
  state.slopes.resize(n);
  for (size_t i = 0; i < n; ++i) {
    state.slopes[i].coordinate = f.coordinates[i];
    if (f.moment_arm_functions.empty()) {
      const int wrt = static_cast<int>(i);
      state.slopes[i].dL_dq = f.length_function->CalcPartialN(x, std::span<const int>(&wrt, 1));
    } else {
      state.slopes[i].dL_dq = -f.moment_arm_functions[i]->CalcN(x);
    }
  }
  state.speed_function = f.lengthening_speed_function.get();
}

void GeometryPath::CalcState(std::span<const double> q, std::span<const Transform> X_GB,
                             PathState& state, bool with_arc_points) const {
  state.points.clear();
  state.slopes.clear();
  state.speed_function = nullptr;
  state.stale_tangent_points = 0;
  if (function_path_) {
    state.e_G.clear();
    state.segment_length.clear();
    state.arc_G.clear();
    CalcFunctionState(q, state);
    return;
  }
  state.points.reserve(points_.size() + 4 * wraps_.size());  // room for every tangent point
  state.arc_G.resize(with_arc_points ? 2 * wraps_.size() : 0);
  for (std::vector<Vec3>& arc : state.arc_G) arc.clear();
  for (size_t i = 0; i < points_.size(); ++i) {
    const PathPoint& point = points_[i];
    if (!point.IsActive(q)) continue;
    PathPointState s;
    s.point = static_cast<int>(i);
    s.body = point.body;
    s.p_BP = point.CalcLocationInBody(q);
    s.p_GP = X_GB[point.body] * s.p_BP;
    if (point.kind == PathPointKind::kMoving) {
      s.coordinates = point.coordinates;
      s.dp_BP_dq = point.CalcLocationDerivatives(q);
    }
    state.points.push_back(s);
  }
  if (state.points.size() < 2) {
    throw Error(where_, component_,
                "only " + std::to_string(state.points.size()) +
                    " of the path's points are active at this pose; a path needs two");
  }
  // The wrapping passes end with the segments of the path they leave, unless they stop early.
  if (!ApplyWraps(q, X_GB, state, with_arc_points)) CalcSegments(state);
}

void GeometryPath::CalcSegments(PathState& state) {
  const size_t n = state.points.size() - 1;
  state.e_G.resize(n);
  state.segment_length.resize(n);
  state.length = 0.0;
  for (size_t i = 0; i < n; ++i) {
    const PathPointState& a = state.points[i];
    if (a.arc_length_to_next >= 0.0) {
      state.e_G[i] = Vec3::Zero();
      state.segment_length[i] = a.arc_length_to_next;
    } else {
      const Vec3 d = state.points[i + 1].p_GP - a.p_GP;
      const double length = d.norm();
      // Coincident points have no direction: NaN, as OpenSim, so derivatives show it.
      state.e_G[i] = length > 0.0 ? Vec3(d / length)
                                  : Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
      state.segment_length[i] = length;
    }
    state.length += state.segment_length[i];
  }
}

// OpenSim's GeometryPath::applyWrapObjects for one wrap object in one pass: its tangent points
// from a previous pass are removed; then, among the segments between the first and last active
// points of its range (tangent points of other objects included, the arcs over them excluded),
// the first that it must wrap (a mandatory wrap) or else the one whose wrapping adds the least
// length is replaced by P-T1, the arc, T2-S. Returns false when the range has no active point
// (OpenSim then abandons wrapping for the whole path).
bool GeometryPath::ApplyWrap(int w, std::span<const double> q, std::span<const Transform> X_GB,
                             PathState& state, WrapOutcome& outcome, TangentPointReads& reads,
                             bool with_arc_points) const {
  RemoveTangentPoints(w, state);
  if (with_arc_points) ClearArcs(w, state);
  outcome = WrapOutcome::kNoWrap;
  const PathWrap& wrap = wraps_[static_cast<size_t>(w)];
  if (!wrap.active || !wrap.surface) return true;
  int first = -1, last = -1;
  for (int p = wrap.first_point; p <= wrap.last_point && first < 0; ++p) {
    if (points_[static_cast<size_t>(p)].IsActive(q)) first = p;
  }
  for (int p = wrap.last_point; p >= wrap.first_point && last < 0; --p) {
    if (points_[static_cast<size_t>(p)].IsActive(q)) last = p;
  }
  int start = -1, end = -1;
  for (size_t k = 0; k < state.points.size(); ++k) {
    if (state.points[k].point == first) start = static_cast<int>(k);
    if (state.points[k].point == last) end = static_cast<int>(k);
  }
  if (start < 0 || end < 0) return false;
  const Transform X_GW = X_GB[wrap.body] * wrap.X_BW;
  const Transform X_WG = X_GW.Inverse();
  WrapOptions options = wrap.options;
  options.single_wrap = wraps_.size() == 1 && refinement_ != CylinderRefinement::kAlways;
  options.t2_checked_after_t1_moves = refinement_ == CylinderRefinement::kSeveralWraps;
  options.with_arc_points = with_arc_points;
  if (wrap.second_body != model::kNone) options.X_WV = X_WG * X_GB[wrap.second_body] * wrap.X_BV;
  double best_change = std::numeric_limits<double>::infinity();
  int best_segment = -1;
  WrapResult best;
  for (int k = start; k < end; ++k) {
    const PathPointState& a = state.points[static_cast<size_t>(k)];
    const PathPointState& b = state.points[static_cast<size_t>(k) + 1];
    if (a.arc_length_to_next >= 0.0) continue;  // the arc over another surface
    // The surface sees the points where they are now.
    const Vec3 p_WP = X_WG * reads.CurrentLocation(a), p_WS = X_WG * reads.CurrentLocation(b);
    WrapResult result = wrap.surface->Wrap(p_WP, p_WS, options);
    // As OpenSim, the outcome reported is the last segment's (or the mandatory one's).
    outcome = result.wrapped        ? WrapOutcome::kWrapped
              : result.point_inside ? WrapOutcome::kPointInside
                                    : WrapOutcome::kNoWrap;
    if (!result.wrapped) continue;
    if (result.mandatory) {
      best_segment = k;
      best = std::move(result);
      break;
    }
    // OpenSim measures the change with the ground locations it has read (and now reads).
    reads.Read(state.points[static_cast<size_t>(k)]);
    reads.Read(state.points[static_cast<size_t>(k) + 1]);
    double wrapped_length = 0.0;
    Vec3 p_G = a.p_GP;  // where the path is so far
    if (result.on_first) {
      wrapped_length += (X_GW * result.p_WT1 - p_G).norm() + result.arc_length;
      p_G = X_GW * result.p_WT2;
    }
    if (result.on_second) {
      wrapped_length += (X_GW * result.p_WT3 - p_G).norm() + result.second_arc_length;
      p_G = X_GW * result.p_WT4;
    }
    const double change = wrapped_length + (b.p_GP - p_G).norm() - (b.p_GP - a.p_GP).norm();
    if (change < best_change) {
      best_change = change;
      best_segment = k;
      best = std::move(result);
    }
  }
  if (best_segment < 0) return true;
  // The tangent points, in order; those over a second frame are fixed to its body.
  std::array<PathPointState, 4> tangents;
  int count = 0;
  const auto add = [&](int which, const Vec3& p_WT, int body, double arc_length) {
    PathPointState& t = tangents[static_cast<size_t>(count++)];
    t.wrap = w;
    t.tangent = which;
    t.body = body;
    t.p_GP = X_GW * p_WT;
    t.p_BP = body == wrap.body ? Vec3(wrap.X_BW * p_WT) : Vec3(X_GB[body].Inverse() * t.p_GP);
    t.arc_length_to_next = arc_length;
    reads.Place(t);
  };
  if (best.on_first) {
    add(0, best.p_WT1, wrap.body, best.arc_length);
    add(1, best.p_WT2, wrap.body, -1.0);
  }
  if (best.on_second) {
    add(2, best.p_WT3, wrap.second_body, best.second_arc_length);
    add(3, best.p_WT4, wrap.second_body, -1.0);
  }
  if (with_arc_points) {
    std::vector<Vec3>& arc = state.arc_G[static_cast<size_t>(PathState::ArcIndex(w, 0))];
    for (const Vec3& p_WA : best.arc_points) arc.push_back(X_GW * p_WA);
    std::vector<Vec3>& second = state.arc_G[static_cast<size_t>(PathState::ArcIndex(w, 2))];
    for (const Vec3& p_WA : best.second_arc_points) second.push_back(X_GW * p_WA);
  }
  state.points.insert(state.points.begin() + best_segment + 1, tangents.begin(),
                      tangents.begin() + count);
  return true;
}

void TangentPointReads::Reset(int num_wraps) {
  const size_t n = static_cast<size_t>(num_wraps);
  read.assign(n, {false, false, false, false});
  p_BP_read.resize(n);
  p_GP_read.resize(n);
  p_GP_current.resize(n);
}

void TangentPointReads::Read(PathPointState& point) {
  if (point.wrap < 0) return;
  const size_t w = static_cast<size_t>(point.wrap);
  const size_t which = static_cast<size_t>(point.tangent);
  if (!read[w][which]) {
    read[w][which] = true;
    p_BP_read[w][which] = point.p_BP;
    p_GP_read[w][which] = point.p_GP;
  }
  point.p_BP = p_BP_read[w][which];
  point.p_GP = p_GP_read[w][which];
}

void TangentPointReads::Place(PathPointState& point) {
  const size_t w = static_cast<size_t>(point.wrap);
  const size_t which = static_cast<size_t>(point.tangent);
  p_GP_current[w][which] = point.p_GP;
  point.p_BP_placed = point.p_BP;
  if (read[w][which]) {
    point.p_BP = p_BP_read[w][which];
    point.p_GP = p_GP_read[w][which];
  }
}

Vec3 TangentPointReads::CurrentLocation(const PathPointState& point) const {
  if (point.wrap < 0) return point.p_GP;
  const size_t which = static_cast<size_t>(point.tangent);
  return p_GP_current[static_cast<size_t>(point.wrap)][which];
}

void GeometryPath::ClearArcs(int w, PathState& state) {
  state.arc_G[static_cast<size_t>(PathState::ArcIndex(w, 0))].clear();
  state.arc_G[static_cast<size_t>(PathState::ArcIndex(w, 2))].clear();
}

void GeometryPath::RemoveTangentPoints(int w, PathState& state) {
  // A wrap's tangent points (two, or up to four over two frames) are next to each other.
  const auto first = std::find_if(state.points.begin(), state.points.end(),
                                  [w](const PathPointState& p) { return p.wrap == w; });
  const auto last =
      std::find_if(first, state.points.end(), [w](const PathPointState& p) { return p.wrap != w; });
  state.points.erase(first, last);
}

// OpenSim's GeometryPath::applyWrapObjects: the wrap objects in the listed order, once for a
// path with one of them; with several, the passes repeat (at most 8) until the length changes
// by less than 0.5 mm, each object rewrapping the path the others left. After the first pass,
// when the first object does not wrap and the second has a point inside it, the two swap.
bool GeometryPath::ApplyWraps(std::span<const double> q, std::span<const Transform> X_GB,
                              PathState& state, bool with_arc_points) const {
  state.stale_tangent_points = 0;
  const int num_wraps = static_cast<int>(wraps_.size());
  if (num_wraps == 0) return false;
  std::vector<int>& order = state.wrap_passes.order;
  order.resize(static_cast<size_t>(num_wraps));
  for (int i = 0; i < num_wraps; ++i) order[static_cast<size_t>(i)] = i;
  std::vector<WrapOutcome>& outcomes = state.wrap_passes.outcomes;
  outcomes.assign(static_cast<size_t>(num_wraps), WrapOutcome::kNoWrap);
  TangentPointReads& reads = state.wrap_passes.reads;
  reads.Reset(num_wraps);
  const int max_passes = num_wraps < 2 ? 1 : kMaxWrapPasses;
  double last_length = std::numeric_limits<double>::infinity();
  for (int pass = 0; pass < max_passes; ++pass) {
    for (int i = 0; i < num_wraps; ++i) {
      if (!ApplyWrap(order[static_cast<size_t>(i)], q, X_GB, state,
                     outcomes[static_cast<size_t>(i)], reads, with_arc_points)) {
        return false;
      }
    }
    for (PathPointState& point : state.points) reads.Read(point);
    CalcSegments(state);
    state.stale_tangent_points = 0;
    for (const PathPointState& point : state.points) {
      if (point.wrap >= 0 && reads.CurrentLocation(point) != point.p_GP) {
        ++state.stale_tangent_points;
      }
    }
    if (std::abs(state.length - last_length) < kWrapPassTolerance) break;
    last_length = state.length;
    if (pass == 0 && num_wraps > 1 && outcomes[0] == WrapOutcome::kNoWrap &&
        outcomes[1] == WrapOutcome::kPointInside) {
      std::swap(order[0], order[1]);
      RemoveTangentPoints(0, state);
      if (with_arc_points) ClearArcs(0, state);
      if (pass + 1 == max_passes) return false;  // the path changed after its segments
    }
  }
  return true;
}

}  // namespace sinew::paths

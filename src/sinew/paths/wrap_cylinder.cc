#include <sinew/common/error.h>
#include <sinew/paths/wrap_cylinder.h>
#include <sinew/paths/wrap_tangents.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sinew::paths {
namespace {

constexpr double kPi = std::numbers::pi;
// OpenSim refines tangent points (paths with several wrap objects) until the segment and the
// helix leave the cylinder's axis at angles within 0.1 degree, restarting at most 100 times; it
// tests tangency at the helix's second sample, the helix being sampled every 2 mm.
constexpr double kTangencyTolerance = 0.1 * kPi / 180.0;
const double kCosTangencyTolerance = std::cos(kTangencyTolerance);
constexpr int kMaxRefinements = 100;
constexpr double kHelixSampleSpacing = 0.002;
// Arc points returned for drawing: at most this many segments.
constexpr int kMaxArcSegments = 100;
// OpenSim slides a tangent point along the cylinder only within this distance (m) (a segment
// of +-10 m about the point, with 1e-5 of slack on its parameter).
constexpr double kMaxSlide = 10.0 * (1.0 + 2e-5);
constexpr double kMinSlideDirection = 1e-5 / 20.0;

Vec3 AxisPointAt(double z) { return {0.0, 0.0, z}; }
Vec3 Radial(const Vec3& p_W) { return {p_W.x(), p_W.y(), 0.0}; }

// The tangent points of the cross-section circle at the height of p_W (|radial| > radius).
CircleTangents CrossSectionTangents(const Vec3& p_W, double radius) {
  CircleTangents tangents = CalcCircleTangents(Radial(p_W), Vec3::UnitZ(), radius);
  tangents.plus.z() = p_W.z();
  tangents.minus.z() = p_W.z();
  return tangents;
}

// Where the line through P and S comes closest to the cylinder's axis: its parameter t along
// P -> S and the point itself. False when the line is parallel to the axis.
bool ClosestApproachToAxis(const Vec3& p_WP, const Vec3& p_WS, double* t, Vec3* p_WM) {
  const Vec3 d = p_WS - p_WP;
  const double radial_squared = Radial(d).squaredNorm();
  if (radial_squared <= 1e-13 * d.squaredNorm()) return false;
  *t = -Radial(p_WP).dot(Radial(d)) / radial_squared;
  *p_WM = p_WP + *t * d;
  return true;
}

double AngleBetween(const Vec3& a, const Vec3& b) {
  return std::acos(std::clamp(a.dot(b) / (a.norm() * b.norm()), -1.0, 1.0));
}

// OpenSim's choice of side under a quadrant: by which preliminary tangent points lie on the
// active side. Also says whether the apex point is taken on the far side of the cylinder.
TangentPair ChooseActiveSidePair(const CircleTangents& from_p, const CircleTangents& from_s,
                                 const WrapQuadrant& quadrant, bool* far_apex) {
  const double alpha = AngleBetween(Radial(from_p.plus), Radial(from_s.minus));
  const double beta = AngleBetween(Radial(from_p.minus), Radial(from_s.plus));
  const TangentPair plus_minus{from_p.plus, from_s.minus};
  const TangentPair minus_plus{from_p.minus, from_s.plus};
  const bool p_plus = quadrant.OnActiveSide(from_p.plus);
  const bool p_minus = quadrant.OnActiveSide(from_p.minus);
  bool take_plus_minus = false;
  if (p_plus != p_minus) {
    take_plus_minus = p_plus;
  } else if (p_plus || quadrant.OnActiveSide(from_s.plus)) {
    // Both or neither of P's candidates are active: S's candidates decide.
    take_plus_minus = !quadrant.OnActiveSide(from_s.plus);
  } else if (quadrant.OnActiveSide(from_s.minus)) {
    take_plus_minus = true;
  } else {
    // No candidate is on the active side.
    *far_apex = true;
    return alpha > beta ? plus_minus : minus_plus;
  }
  *far_apex = take_plus_minus ? alpha > beta : alpha <= beta;
  return take_plus_minus ? plus_minus : minus_plus;
}

// OpenSim's slide of the preliminary tangent points along the cylinder: an apex point on the
// surface, on the bisecting side at the height where the segment is nearest the axis in the
// ratio of P's and S's distances from it, defines with P and S a plane; each tangent point moves
// along its generator to that plane, if that brings it toward the other point's height.
void SlideToApexPlane(const Vec3& p_WP, const Vec3& p_WS, double radius, bool far_apex,
                      TangentPair* pair) {
  const double rho_p = Radial(p_WP).norm();
  const double rho_s = Radial(p_WS).norm();
  const Vec3 p_WM = p_WP + rho_p / (rho_p + rho_s) * (p_WS - p_WP);
  const Vec3 p_WA = AxisPointAt(p_WM.z());
  const Vec3 side_normal = (p_WP - p_WA).normalized().cross((p_WS - p_WA).normalized());
  if (side_normal.norm() < 1e-12) return;  // P, S and the axis point in a line
  const Vec3 outward = Vec3::UnitZ().cross(side_normal).normalized();
  const Vec3 apex_1 = p_WA + radius * outward;
  const Vec3 apex_2 = p_WA - radius * outward;
  const bool first_is_near = (p_WM - apex_1).squaredNorm() < (p_WM - apex_2).squaredNorm();
  const Vec3 apex = first_is_near != far_apex ? apex_1 : apex_2;
  Vec3 normal = (p_WP - apex).normalized().cross((p_WS - apex).normalized());
  if (normal.norm() < 1e-12) return;
  normal.normalize();
  if (std::abs(normal.z()) < kMinSlideDirection) return;
  // Height at which the generator through `t` meets the plane through P with `normal`.
  const auto slid = [&](const Vec3& t, double* z) {
    const double dz = normal.dot(p_WP - t) / normal.z();
    *z = t.z() + dz;
    return std::abs(dz) <= kMaxSlide;
  };
  const double height = std::abs(p_WP.z() - p_WS.z());
  double z = 0.0;
  if (slid(pair->t1, &z) && std::abs(z - p_WS.z()) < height) pair->t1.z() = z;
  if (slid(pair->t2, &z) && std::abs(z - p_WP.z()) < height) pair->t2.z() = z;
}

// The helix from T1 to T2: the turn about the axis (rad, signed, counter-clockwise about z
// positive) and the rise along it (m).
struct Helix {
  double turn;
  double rise;
  double Length(double radius) const {
    const double arc = radius * turn;
    return std::sqrt(arc * arc + rise * rise);
  }
  // T1 turned by s turn about z and raised by s rise.
  Vec3 PointAt(const Vec3& p_WT1, double s) const {
    const double c = std::cos(s * turn), n = std::sin(s * turn);
    return {c * p_WT1.x() - n * p_WT1.y(), n * p_WT1.x() + c * p_WT1.y(), p_WT1.z() + s * rise};
  }
};

// The short way round, or the long way (the other direction) when `long_way`.
Helix CalcHelix(const TangentPair& pair, bool long_way) {
  const Vec3 u1 = Radial(pair.t1);
  const Vec3 u2 = Radial(pair.t2);
  double turn = std::atan2(u1.cross(u2).z(), u1.dot(u2));
  if (long_way) turn = -std::copysign(2.0 * kPi - std::abs(turn), turn);
  return {turn, pair.t2.z() - pair.t1.z()};
}

// OpenSim's tangency refinement of one tangent point T (from path point X) against the helix
// sample W next to T: when the segment X-T and the helix's start T-W leave the cylinder's axis
// at angles a1, a2 (in [0, pi]) differing by more than the tolerance, T moves along its
// generator 1.5 times toward where the line X-W passes it. The refinement moves T and W along z
// only (W's position about the axis changes only with the number of samples), so what depends
// on their x and y is computed when W's changes (SetSample), and a step costs a square root:
// |a1 - a2| <= tol exactly when cos(a1 - a2) = cos a1 cos a2 + sin a1 sin a2 >= cos tol (no arc
// cosines), both sides times |X-T| |T-W|. Every quantity is formed as OpenSim's vectors' would
// be (x^2 + y^2 first, then + z^2), so the steps are the same to the last bit.
class TangentPointRefinement {
 public:
  TangentPointRefinement(const Vec3& p_WX, const Vec3& p_WT)
      : x_z_(p_WX.z()),
        t_x_(p_WT.x()),
        t_y_(p_WT.y()),
        d1_x_(p_WT.x() - p_WX.x()),
        d1_y_(p_WT.y() - p_WX.y()),
        x_x_(p_WX.x()),
        x_y_(p_WX.y()) {
    d1_radial_squared_ = d1_x_ * d1_x_ + d1_y_ * d1_y_;
  }
  // W's position about the axis is now (w_x, w_y).
  void SetSample(double w_x, double w_y) {
    const double d2_x = w_x - t_x_, d2_y = w_y - t_y_;
    d2_radial_squared_ = d2_x * d2_x + d2_y * d2_y;
    radial_ = std::sqrt(d1_radial_squared_ * d2_radial_squared_);
    // Where the line X-W passes T's generator: X + slide (W - X), of which only z moves.
    const double e_x = w_x - x_x_, e_y = w_y - x_y_;
    const double e_radial_squared = e_x * e_x + e_y * e_y;
    movable_ = e_radial_squared > 0.0;
    slide_ = movable_ ? (d1_x_ * e_x + d1_y_ * e_y) / e_radial_squared : 0.0;
  }
  // One step with W at height w_z; T at height *t_z. True if T moved.
  bool Step(double w_z, double* t_z) const {
    const double d1_z = *t_z - x_z_, d2_z = w_z - *t_z;
    const double lengths_squared =
        (d1_radial_squared_ + d1_z * d1_z) * (d2_radial_squared_ + d2_z * d2_z);
    if (d1_z * d2_z + radial_ >= kCosTangencyTolerance * std::sqrt(lengths_squared)) {
      return false;
    }
    if (!movable_) return false;
    const double z_nearest = x_z_ + slide_ * (w_z - x_z_);
    *t_z += 1.5 * (z_nearest - *t_z);
    return true;
  }

 private:
  double x_z_, t_x_, t_y_, d1_x_, d1_y_, x_x_, x_y_;
  double d1_radial_squared_ = 0.0, d2_radial_squared_ = 0.0, radial_ = 0.0, slide_ = 0.0;
  bool movable_ = false;
};

// OpenSim's refinement (paths with several wrap objects): T1 against the helix's sample at
// s = 1 / samples, T2 against the one at 1 - 1 / samples, the helix sampled every 2 mm, until
// neither moves or 100 times. The points move along their generators only, so the helix's turn
// and the samples' positions about the axis stay; those are recomputed only when the number
// of samples changes, and the heights follow T1 and the rise. `t2_after_t1`: T2's sample is
// on the helix started at T1 as T1's step left it (OpenSim 4.4.1 and later), else as the step
// found it (WrapOptions::t2_checked_after_t1_moves).
void RefineTangency(const Vec3& p_WP, const Vec3& p_WS, double radius, bool t2_after_t1,
                    Helix* helix, TangentPair* pair) {
  const double arc = radius * helix->turn;
  const double arc_squared = arc * arc;
  TangentPointRefinement first(p_WP, pair->t1), second(p_WS, pair->t2);
  int last_samples = -1;
  double s = 0.0;
  // The number of samples is the helix's length (Helix::Length) over 2 mm, truncated. Its
  // square root and division are taken only when the squared length leaves the range that
  // gives the last number with a margin of 1e-12 (far beyond their rounding), so the number
  // is always the one they give.
  double same_above = 0.0, same_below = -1.0;
  for (int refinement = 0; refinement < kMaxRefinements; ++refinement) {
    const double rise = helix->rise;
    const double length_squared = arc_squared + rise * rise;
    if (!(length_squared > same_above && length_squared < same_below)) {
      const int samples = static_cast<int>(std::sqrt(length_squared) / kHelixSampleSpacing);
      if (samples < 2) break;
      const double low = samples * kHelixSampleSpacing;
      const double high = (samples + 1) * kHelixSampleSpacing;
      same_above = low * low * (1.0 + 1e-12);
      same_below = high * high * (1.0 - 1e-12);
      if (samples != last_samples) {
        last_samples = samples;
        s = 1.0 / samples;
        const Vec3 after_t1 = helix->PointAt(pair->t1, s);
        const Vec3 before_t2 = helix->PointAt(pair->t1, 1.0 - s);
        first.SetSample(after_t1.x(), after_t1.y());
        second.SetSample(before_t2.x(), before_t2.y());
      }
    }
    // OpenSim 4.4.1 and later check T2 against the previous helix started at the new T1;
    // earlier versions against the previous helix itself.
    const double t1_z = pair->t1.z();
    const bool moved_t1 = first.Step(t1_z + s * rise, &pair->t1.z());
    const double helix_start = t2_after_t1 ? pair->t1.z() : t1_z;
    const bool moved_t2 = second.Step(helix_start + (1.0 - s) * rise, &pair->t2.z());
    if (!moved_t1 && !moved_t2) break;
    helix->rise = pair->t2.z() - pair->t1.z();  // the turn stays (radial positions unchanged)
  }
}

}  // namespace

WrapCylinder::WrapCylinder(double radius, double length, WrapQuadrant quadrant)
    : radius_(radius), length_(length), quadrant_(quadrant) {
  if (!(radius > 0.0) || !std::isfinite(radius) || !(length > 0.0) || !std::isfinite(length)) {
    throw Error("WrapCylinder: the radius and the length must be positive and finite");
  }
}

WrapResult WrapCylinder::Wrap(const Vec3& p_WP, const Vec3& p_WS,
                              const WrapOptions& options) const {
  WrapResult result;
  if (Radial(p_WP).norm() < radius_ || Radial(p_WS).norm() < radius_) {
    result.point_inside = true;
    return result;
  }

  // Whether the segment crosses the (infinite) cylinder: its closest approach to the axis lies
  // between P and S and within the radius.
  double t = 0.0;
  Vec3 p_WM = Vec3::Zero();
  const bool has_approach = ClosestApproachToAxis(p_WP, p_WS, &t, &p_WM);
  const bool crosses = has_approach && Radial(p_WM).norm() < radius_ && t > 0.0 && t < 1.0;

  const CircleTangents from_p = CrossSectionTangents(p_WP, radius_);
  const CircleTangents from_s = CrossSectionTangents(p_WS, radius_);
  TangentPair pair;
  bool far_apex = false;
  bool long_way = false;
  if (!quadrant_.constrained()) {
    if (!crosses) return result;
    result.mandatory = true;
    pair = ChooseClosestPair(from_p, AxisPointAt(p_WP.z()), from_s, AxisPointAt(p_WS.z()));
  } else {
    if (quadrant_.OnActiveSide(p_WP) || quadrant_.OnActiveSide(p_WS)) {
      // Without a closest approach (a segment parallel to the axis) OpenSim's point is undefined
      // and no wrap results.
      if (!has_approach) return result;
      const QuadrantEngagement engagement =
          EngageOnActiveSide(quadrant_, p_WP, p_WS, p_WM, crosses);
      if (engagement == QuadrantEngagement::kNoWrap) return result;
      result.mandatory = engagement == QuadrantEngagement::kMandatory;
    }
    pair = ChooseActiveSidePair(from_p, from_s, quadrant_, &far_apex);
    const Vec3 path_direction = (pair.t1 - p_WP) + (pair.t2 - p_WS);
    const Vec3 radial_sum = Radial(pair.t1) + Radial(pair.t2);
    long_way = radial_sum.dot(path_direction) < 0.0;
  }
  SlideToApexPlane(p_WP, p_WS, radius_, far_apex, &pair);

  // The wrap counts only if a tangent point lies along the cylinder's length.
  const double half_length = 0.5 * length_;
  if (std::abs(pair.t1.z()) > half_length && std::abs(pair.t2.z()) > half_length) return result;

  Helix helix = CalcHelix(pair, long_way);
  if (!options.single_wrap) {
    RefineTangency(p_WP, p_WS, radius_, options.t2_checked_after_t1_moves, &helix, &pair);
  }

  result.wrapped = true;
  result.p_WT1 = pair.t1;
  result.p_WT2 = pair.t2;
  result.arc_length = helix.Length(radius_);
  if (!options.with_arc_points) return result;
  const int segments = std::clamp(
      static_cast<int>(std::ceil(result.arc_length / kHelixSampleSpacing)), 1, kMaxArcSegments);
  result.arc_points.reserve(segments + 1);
  for (int i = 0; i <= segments; ++i) {
    result.arc_points.push_back(helix.PointAt(pair.t1, static_cast<double>(i) / segments));
  }
  return result;
}

}  // namespace sinew::paths

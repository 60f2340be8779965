#include <sinew/common/error.h>
#include <sinew/paths/wrap_double_cylinder_obst.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace sinew::paths {
namespace {

using Vec2 = Eigen::Vector2d;

// OpenSim's clearance between a cylinder and a point inside it (m): such a cylinder shrinks to
// pass this far inside the point.
constexpr double kClearance = 1e-4;
// OpenSim gives up on a cylinder when a point's squared distance from its axis is below this
// number (m^2, compared with the 0.1 mm clearance as if it were a squared length: 1 cm).
constexpr double kNoRoomSquared = 1e-4;
// Newton's method on the crossing line: OpenSim's stopping rule (the sum of the absolute
// changes of V's entry point below 1e-12 m) and its limit of 50 steps.
constexpr double kCrossingTolerance = 1e-12;
constexpr int kMaxCrossingSteps = 50;
// Central-difference step for the Newton matrix (m).
constexpr double kJacobianStep = 1e-7;
// Arc points for drawing: one every 5 degrees.
constexpr double kArcPointStep = 5.0 * std::numbers::pi / 180.0;

double Cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }
Vec2 Flat(const Vec3& p) { return p.head<2>(); }
Vec3 Lift(const Vec2& p, double z) { return {p.x(), p.y(), z}; }

// In a cross-section, the point where the path from `p` (outside the circle of radius r about
// the origin) touches the circle when it goes round the circle counter-clockwise (turn +1) or
// clockwise (turn -1): leaving p (`leaving`), or arriving at p from the circle.
Vec2 Tangent(const Vec2& p, double r, int turn, bool leaving) {
  const double d2 = p.squaredNorm();
  const double side = r * std::sqrt(std::max(d2 - r * r, 0.0)) / d2;
  const Vec2 normal(-p.y(), p.x());
  return (r * r / d2) * p + (leaving ? turn : -turn) * side * normal;
}

// The angle between two points of the circle of radius r from their chord, in [0, pi].
double ChordAngle(const Vec2& a, const Vec2& b, double r) {
  return std::acos(std::clamp(1.0 - 0.5 * (a - b).squaredNorm() / (r * r), -1.0, 1.0));
}

// Whether the whole line through a and b (not only the segment) passes within r of the axis.
bool LineWithin(const Vec3& a, const Vec3& b, double r) {
  const double c = Cross(Flat(a), Flat(b));
  return c * c / (Flat(b) - Flat(a)).squaredNorm() <= r * r;
}

// The radius a cylinder keeps with a point at squared distance d2 from its axis.
double Shrunk(double r, double d2) {
  return d2 < (r + kClearance) * (r + kClearance) ? std::sqrt(d2) - kClearance : r;
}

// The path over one cylinder (its frame): P to Q, the helix Q to T, T to S.
struct OneCylinder {
  bool wraps = false;
  Vec3 q = Vec3::Zero(), t = Vec3::Zero();
  double arc = 0.0;    // the helix's length (m)
  double angle = 0.0;  // its turn (rad)
  double radius = 0.0;
};

OneCylinder WrapOne(const Vec3& p, const Vec3& s, double r, int turn) {
  OneCylinder one;
  const double dp2 = Flat(p).squaredNorm(), ds2 = Flat(s).squaredNorm();
  if (dp2 < kNoRoomSquared || ds2 < kNoRoomSquared) return one;
  r = Shrunk(r, std::min(dp2, ds2));
  const Vec2 q = Tangent(Flat(p), r, turn, true), t = Tangent(Flat(s), r, turn, false);
  if (turn * Cross(q, t) < 0.0) return one;  // more than half a turn: not this way
  const double pq = (q - Flat(p)).norm(), ts = (Flat(s) - t).norm();
  one.angle = ChordAngle(q, t, r);
  const double arc = r * one.angle, unrolled = pq + arc + ts;
  const double rise = s.z() - p.z();
  const double z_q = unrolled > 0.0 ? p.z() + rise * pq / unrolled : p.z();
  const double z_t = unrolled > 0.0 ? s.z() - rise * ts / unrolled : s.z();
  one.wraps = true;
  one.q = Lift(q, z_q);
  one.t = Lift(t, z_t);
  one.arc = std::hypot(arc, z_t - z_q);
  one.radius = r;
  return one;
}

// Both cylinders for a guess x of the point T where the path reaches V (in V): U's tangent
// point Q from x, its height from the path P-U-x unrolled, then V's tangent point T from Q and
// its height from the path Q-V-S unrolled. At the solution T = x.
struct Crossing {
  bool valid = false;
  Vec3 q_U, Q_U, T_V, t_V;  // q and Q on U (in W), T and t on V (in V)
  double arc_u = 0.0, arc_v = 0.0, angle_u = 0.0, angle_v = 0.0;
  Vec2 q, Q, T, t;  // cross-section tangent points, each in its cylinder's frame
};

struct CrossingData {
  Vec3 p_WP, p_VS;
  Transform X_WV, X_VW;
  double ru, rv;
  int turn_u, turn_v;
  Vec2 q, t;  // the tangent points from P (on U) and from S (on V), which x does not move
};

Crossing CalcCrossing(const CrossingData& d, const Vec3& x_V) {
  Crossing c;
  c.q = d.q;
  c.t = d.t;
  const Vec3 x_W = d.X_WV * x_V;
  if (Flat(x_W).squaredNorm() < d.ru * d.ru) return c;  // x inside U: no tangent
  c.Q = Tangent(Flat(x_W), d.ru, d.turn_u, false);
  const double pq = (d.q - Flat(d.p_WP)).norm(), qx = (Flat(x_W) - c.Q).norm();
  c.angle_u = ChordAngle(d.q, c.Q, d.ru);
  const double unrolled_u = pq + d.ru * c.angle_u + qx;
  const double rise_u = x_W.z() - d.p_WP.z();
  c.q_U = Lift(d.q, d.p_WP.z() + rise_u * pq / unrolled_u);
  c.Q_U = Lift(c.Q, x_W.z() - rise_u * qx / unrolled_u);
  const Vec3 Q_V = d.X_VW * c.Q_U;
  if (Flat(Q_V).squaredNorm() < d.rv * d.rv) return c;  // Q inside V: no tangent
  c.T = Tangent(Flat(Q_V), d.rv, d.turn_v, true);
  const double qt = (c.T - Flat(Q_V)).norm(), ts = (Flat(d.p_VS) - d.t).norm();
  c.angle_v = ChordAngle(c.T, d.t, d.rv);
  const double unrolled_v = qt + d.rv * c.angle_v + ts;
  const double rise_v = d.p_VS.z() - Q_V.z();
  c.T_V = Lift(c.T, Q_V.z() + rise_v * qt / unrolled_v);
  c.t_V = Lift(d.t, d.p_VS.z() - rise_v * ts / unrolled_v);
  c.arc_u = std::hypot(d.ru * c.angle_u, c.Q_U.z() - c.q_U.z());
  c.arc_v = std::hypot(d.rv * c.angle_v, c.t_V.z() - c.T_V.z());
  c.valid = true;
  return c;
}

// The crossing line tangent to both cylinders, by Newton's method on T(x) - x from `x_V`; none
// when a tangent does not exist on the way or the steps do not settle.
std::optional<Crossing> SolveCrossing(const CrossingData& d, Vec3 x_V) {
  for (int step = 0; step < kMaxCrossingSteps; ++step) {
    const Crossing c = CalcCrossing(d, x_V);
    if (!c.valid) return std::nullopt;
    const Vec3 residual = c.T_V - x_V;
    if (residual.cwiseAbs().sum() < kCrossingTolerance) return c;
    Mat3 jacobian;
    for (int k = 0; k < 3; ++k) {
      Vec3 dx = Vec3::Zero();
      dx[k] = kJacobianStep;
      const Crossing plus = CalcCrossing(d, x_V + dx), minus = CalcCrossing(d, x_V - dx);
      if (!plus.valid || !minus.valid) return std::nullopt;
      jacobian.col(k) = (plus.T_V - minus.T_V) / (2.0 * kJacobianStep);
    }
    jacobian -= Mat3::Identity();
    x_V -= jacobian.partialPivLu().solve(residual);
    if (!x_V.allFinite()) return std::nullopt;
  }
  return std::nullopt;
}

void AddArcPoints(const Vec3& from, const Vec3& to, double angle, int turn, const Transform& X,
                  std::vector<Vec3>& points) {
  const int steps = 1 + static_cast<int>(angle / kArcPointStep);
  for (int i = 0; i <= steps; ++i) {
    const double fraction = static_cast<double>(i) / steps;
    const Eigen::AngleAxisd turned(turn * fraction * angle, Vec3::UnitZ());
    const Vec3 p = turned * Vec3(from.x(), from.y(), 0.0);
    points.push_back(X * Vec3(p.x(), p.y(), from.z() + fraction * (to.z() - from.z())));
  }
}

}  // namespace

WrapDoubleCylinderObst::WrapDoubleCylinderObst(double radius_u, Direction direction_u,
                                               double radius_v, Direction direction_v)
    : radius_u_(radius_u),
      radius_v_(radius_v),
      direction_u_(direction_u),
      direction_v_(direction_v) {
  if (!(radius_u > 0.0) || !std::isfinite(radius_u) || !(radius_v > 0.0) ||
      !std::isfinite(radius_v)) {
    throw Error("WrapDoubleCylinderObst: the radii must be positive and finite");
  }
}

WrapResult WrapDoubleCylinderObst::Wrap(const Vec3& p_WP, const Vec3& p_WS,
                                        const WrapOptions& options) const {
  const int turn_u = direction_u_ == Direction::kRightHand ? 1 : -1;
  const int turn_v = direction_v_ == Direction::kRightHand ? 1 : -1;
  const Transform& X_WV = options.X_WV;
  const Transform X_VW = X_WV.Inverse();
  const Vec3 p_VP = X_VW * p_WP, p_VS = X_VW * p_WS;

  WrapResult result;
  result.wrapped = true;  // OpenSim reports a wrap even over neither cylinder
  result.on_first = false;
  const auto only_u = [&](const OneCylinder& u) {
    result.on_first = true;
    result.p_WT1 = u.q;
    result.p_WT2 = u.t;
    result.arc_length = u.arc;
    if (options.with_arc_points) {
      AddArcPoints(u.q, u.t, u.angle, turn_u, Transform::Identity(), result.arc_points);
    }
  };
  const auto only_v = [&](const OneCylinder& v) {
    result.on_second = true;
    result.p_WT3 = X_WV * v.q;
    result.p_WT4 = X_WV * v.t;
    result.second_arc_length = v.arc;
    if (options.with_arc_points) {
      AddArcPoints(v.q, v.t, v.angle, turn_v, X_WV, result.second_arc_points);
    }
  };
  // Both cylinders, starting Newton's method from x_V; `fallback` when that fails.
  const auto both = [&](const Vec3& x_V, auto fallback) {
    const double dp2 = Flat(p_WP).squaredNorm(), ds2 = Flat(p_VS).squaredNorm();
    if (dp2 < kNoRoomSquared || ds2 < kNoRoomSquared) return fallback();
    CrossingData d{
        p_WP,   p_VS,   X_WV,         X_VW,        Shrunk(radius_u_, dp2), Shrunk(radius_v_, ds2),
        turn_u, turn_v, Vec2::Zero(), Vec2::Zero()};
    d.q = Tangent(Flat(p_WP), d.ru, turn_u, true);
    d.t = Tangent(Flat(p_VS), d.rv, turn_v, false);
    const std::optional<Crossing> c = SolveCrossing(d, x_V);
    if (!c) return fallback();
    // A cylinder whose turn at the solution goes the wrong way is left out.
    if (turn_u * Cross(c->Q, c->q) > 0.0) {
      const OneCylinder v = WrapOne(p_VP, p_VS, radius_v_, turn_v);
      if (v.wraps) only_v(v);
      return;
    }
    if (turn_v * Cross(c->t, c->T) > 0.0) {
      const OneCylinder u = WrapOne(p_WP, p_WS, radius_u_, turn_u);
      if (u.wraps) only_u(u);
      return;
    }
    result.on_first = result.on_second = true;
    result.p_WT1 = c->q_U;
    result.p_WT2 = c->Q_U;
    result.arc_length = c->arc_u;
    result.p_WT3 = X_WV * c->T_V;
    result.p_WT4 = X_WV * c->t_V;
    result.second_arc_length = c->arc_v;
    if (options.with_arc_points) {
      AddArcPoints(c->q_U, c->Q_U, c->angle_u, turn_u, Transform::Identity(), result.arc_points);
      AddArcPoints(c->T_V, c->t_V, c->angle_v, turn_v, X_WV, result.second_arc_points);
    }
  };
  // V first (also after U turned out not to wrap): then U, from P to where the path meets V.
  const auto v_first = [&] {
    const OneCylinder v = WrapOne(p_VP, p_VS, radius_v_, turn_v);
    if (!v.wraps) return;
    if (LineWithin(p_WP, X_WV * v.q, radius_u_)) {
      both(v.q, [&] { only_v(v); });
    } else {
      only_v(v);
    }
  };
  // OpenSim starts every evaluation with neither cylinder active (docs/wrapping.md).
  if (LineWithin(p_WP, p_WS, radius_u_)) {
    const OneCylinder u = WrapOne(p_WP, p_WS, radius_u_, turn_u);
    if (!u.wraps) {
      if (LineWithin(p_VP, p_VS, radius_v_)) v_first();
      return result;
    }
    if (LineWithin(X_VW * u.t, p_VS, radius_v_)) {
      both(p_VS, [&] { only_u(u); });
    } else {
      only_u(u);
    }
  } else if (LineWithin(p_VP, p_VS, radius_v_)) {
    v_first();
  }
  return result;
}

}  // namespace sinew::paths

#include <sinew/common/error.h>
#include <sinew/paths/wrap_torus.h>

#include <cmath>

namespace sinew::paths {
namespace {

// OpenSim lays a cylinder of the tube's radius along the ring's tangent, this long (m).
constexpr double kTubeCylinderLength = 10000.0;
constexpr int kMaxNewtonSteps = 100;
constexpr int kMaxStepHalvings = 40;

// The line x(u) = p_WA + u n (n a unit vector) and OpenSim's residual along it:
//   g(u) = d/du |x|^2 - 4 R d/du rho(u),   rho(u) = |(x_x, x_y)|, the distance from W's z axis.
// OpenSim's comment calls it the derivative of the squared distance to the ring of radius R;
// that derivative has 2 R, not 4 R, in its second term, so g vanishes where the line is
// stationary in its distance to a circle of radius 2 R.
struct RingResidual {
  Vec3 p_WA;
  Vec3 n;
  double ring_radius;

  double Rho(double u) const {
    const Vec3 x = p_WA + u * n;
    return std::hypot(x.x(), x.y());
  }
  // d rho / du times rho: (c4 u + c3) in OpenSim's terms.
  double RhoRate(double u) const {
    const Vec3 x = p_WA + u * n;
    return x.x() * n.x() + x.y() * n.y();
  }
  double Value(double u) const {
    return 2.0 * (p_WA.dot(n) + u) - 4.0 * ring_radius * RhoRate(u) / Rho(u);
  }
  double Slope(double u) const {
    const double rho = Rho(u);
    const double planar = n.x() * n.x() + n.y() * n.y();
    const double rate = RhoRate(u);
    return 2.0 - 4.0 * ring_radius * (planar * rho * rho - rate * rate) / (rho * rho * rho);
  }
};

// The root of the residual reached from u = 0 (the end p_WA) by Newton steps that never let
// |g| grow (halved until they do not): the root OpenSim's Levenberg-Marquardt solver, started
// at the same end, converges to. Empty when the line meets W's z axis on the way.
std::optional<Vec3> LinePointOfRingResidual(const RingResidual& residual) {
  double u = 0.0;
  if (!(residual.Rho(u) > 0.0)) return std::nullopt;
  double g = residual.Value(u);
  for (int step = 0; step < kMaxNewtonSteps && g != 0.0; ++step) {
    const double slope = residual.Slope(u);
    if (!(std::abs(slope) > 0.0) || !std::isfinite(slope)) break;
    double du = -g / slope;
    bool improved = false;
    for (int halving = 0; halving < kMaxStepHalvings; ++halving, du *= 0.5) {
      if (!(residual.Rho(u + du) > 0.0)) continue;
      const double g_next = residual.Value(u + du);
      if (std::abs(g_next) < std::abs(g)) {
        improved = true;
        u += du;
        g = g_next;
        break;
      }
    }
    if (!improved || std::abs(du) <= 1e-15 * (1.0 + std::abs(u))) break;
  }
  return residual.p_WA + u * residual.n;
}

// Distance from a point to the ring circle of radius R about W's z axis.
double DistanceToRing(const Vec3& p_W, double ring_radius) {
  const double rho = std::hypot(p_W.x(), p_W.y());
  return std::sqrt(
      std::max(0.0, p_W.squaredNorm() + ring_radius * ring_radius - 2.0 * ring_radius * rho));
}

}  // namespace

std::optional<Vec3> FindTorusRingPoint(const Vec3& p_WP, const Vec3& p_WS, double ring_radius,
                                       const WrapQuadrant& quadrant) {
  const Vec3 chord = p_WS - p_WP;
  if (!(chord.norm() > 0.0)) return std::nullopt;
  const Vec3 n = chord.normalized();
  const std::optional<Vec3> from_p = LinePointOfRingResidual({p_WP, n, ring_radius});
  const std::optional<Vec3> from_s = LinePointOfRingResidual({p_WS, -n, ring_radius});
  if (!from_p && !from_s) return std::nullopt;
  const auto nearer = [&](const Vec3& a, const Vec3& b) {
    return DistanceToRing(a, ring_radius) < DistanceToRing(b, ring_radius) ? a : b;
  };
  Vec3 line_point;
  if (!quadrant.constrained()) {
    line_point = !from_p ? *from_s : !from_s ? *from_p : nearer(*from_p, *from_s);
  } else {
    const bool p_active = from_p && quadrant.OnActiveSide(*from_p);
    const bool s_active = from_s && quadrant.OnActiveSide(*from_s);
    if (!p_active && !s_active) return std::nullopt;
    line_point = p_active && s_active ? nearer(*from_p, *from_s) : p_active ? *from_p : *from_s;
  }
  const double rho = std::hypot(line_point.x(), line_point.y());
  if (!(rho > 0.0)) return std::nullopt;
  return Vec3(line_point.x(), line_point.y(), 0.0) * (ring_radius / rho);
}

WrapTorus::WrapTorus(double inner_radius, double outer_radius, WrapQuadrant quadrant)
    : inner_radius_(inner_radius),
      outer_radius_(outer_radius),
      quadrant_(quadrant),
      tube_(inner_radius, kTubeCylinderLength, WrapQuadrant{0, +1}) {
  if (!(outer_radius > inner_radius) || !std::isfinite(outer_radius)) {
    throw Error("WrapTorus: outer_radius must be finite and greater than inner_radius");
  }
}

WrapResult WrapTorus::Wrap(const Vec3& p_WP, const Vec3& p_WS, const WrapOptions& options) const {
  const std::optional<Vec3> p_WC = FindTorusRingPoint(p_WP, p_WS, outer_radius_, quadrant_);
  if (!p_WC) return {};
  // The cylinder's frame Y at the ring point: x toward the torus's axis, y = -z_W, z = x cross y
  // (the ring's tangent). R_WY's columns are Y's axes in W.
  Mat3 R_WY;
  R_WY.col(0) = -*p_WC / outer_radius_;
  R_WY.col(1) = -Vec3::UnitZ();
  R_WY.col(2) = R_WY.col(0).cross(R_WY.col(1));
  const auto to_tube = [&](const Vec3& p_W) -> Vec3 { return R_WY.transpose() * (p_W - *p_WC); };
  const auto from_tube = [&](const Vec3& p_Y) -> Vec3 { return *p_WC + R_WY * p_Y; };

  WrapResult tube = tube_.Wrap(to_tube(p_WP), to_tube(p_WS), options);
  // OpenSim reports a segment the cylinder does not wrap as wrapped with no path on the surface,
  // which its path code then drops: no wrap. A wrap is always a plain one (never mandatory),
  // and a point inside the tube is not reported.
  WrapResult result;
  if (!tube.wrapped) return result;
  result.wrapped = true;
  result.p_WT1 = from_tube(tube.p_WT1);
  result.p_WT2 = from_tube(tube.p_WT2);
  result.arc_length = tube.arc_length;
  result.arc_points.reserve(tube.arc_points.size());
  for (const Vec3& p_Y : tube.arc_points) result.arc_points.push_back(from_tube(p_Y));
  return result;
}

}  // namespace sinew::paths

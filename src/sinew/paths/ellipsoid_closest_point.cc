#include <sinew/paths/ellipsoid_closest_point.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace sinew::paths {
namespace {

// A coordinate this close to zero counts as on the axis or plane (OpenSim's ROUNDOFF_ERROR).
constexpr double kOnPlane = 2e-13;
// Newton on the multiplier t stops when |f(t)| is below this, or after kMaxNewtonSteps.
constexpr double kResidual = 1e-9;
constexpr int kMaxNewtonSteps = 64;

bool NearZero(double x) { return std::abs(x) <= kOnPlane; }

}  // namespace

Eigen::Vector2d CalcClosestPointOnEllipse(double a, double b, double u, double v) {
  const double a2 = a * a, b2 = b * b;
  const double a2u2 = a2 * u * u, b2v2 = b2 * v * v;
  const bool on_y_axis = NearZero(u), on_x_axis = NearZero(v);
  if (on_y_axis && on_x_axis) {
    // At the centre: the end of the shorter semi-axis.
    return a < b ? Eigen::Vector2d(u < 0.0 ? -a : a, v) : Eigen::Vector2d(u, v < 0.0 ? -b : b);
  }
  if (on_y_axis) {
    if (a >= b || std::abs(v) >= b - a2 / b) return {u, v >= 0.0 ? b : -b};
    const double y = b2 * v / (b2 - a2);
    return {a * std::sqrt(std::abs(1.0 - (y / b) * (y / b))), y};
  }
  if (on_x_axis) {
    if (b >= a || std::abs(u) >= a - b2 / a) return {u >= 0.0 ? a : -a, v};
    const double x = a2 * u / (a2 - b2);
    return {x, b * std::sqrt(std::abs(1.0 - (x / a) * (x / a)))};
  }
  // Newton on f(t) = (t + a^2)^2 (t + b^2)^2 - a^2 u^2 (t + b^2)^2 - b^2 v^2 (t + a^2)^2, the
  // closest point being (a^2 u / (t + a^2), b^2 v / (t + b^2)); from 0 inside, from
  // max(a, b) |(u, v)| outside.
  double t = (u / a) * (u / a) + (v / b) * (v / b) < 1.0 ? 0.0 : std::max(a, b) * std::hypot(u, v);
  double P = t + a2, Q = t + b2;
  for (int step = 0; step < kMaxNewtonSteps; ++step) {
    P = t + a2;
    Q = t + b2;
    const double f = P * P * Q * Q - a2u2 * Q * Q - b2v2 * P * P;
    if (std::abs(f) < kResidual) break;
    const double df = 2.0 * (P * Q * (P + Q) - a2u2 * Q - b2v2 * P);
    t -= f / df;
  }
  return {a2 * u / P, b2 * v / Q};
}

Vec3 CalcClosestPointOnEllipsoid(const Vec3& radii, const Vec3& p, int plane_axis,
                                 const Vec3& fallback) {
  if (plane_axis < 0) {
    // On one or more principal planes: the narrowest such cross-section.
    double narrowest = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) {
      if (!NearZero(p[i])) continue;
      const double radii_sum = radii.sum() - radii[i];
      if (radii_sum < narrowest) {
        plane_axis = i;
        narrowest = radii_sum;
      }
    }
  }
  // In the cross-section x_i = p_i, the other two axes in OpenSim's order (y z, z x, x y).
  if (plane_axis >= 0) {
    const int j = (plane_axis + 1) % 3, k = (plane_axis + 2) % 3;
    const Eigen::Vector2d c = CalcClosestPointOnEllipse(radii[j], radii[k], p[j], p[k]);
    Vec3 out;
    out[plane_axis] = p[plane_axis];
    out[j] = c[0];
    out[k] = c[1];
    return out;
  }
  const Vec3 r2 = radii.cwiseProduct(radii);
  const Vec3 r2p2 = r2.cwiseProduct(p.cwiseProduct(p));
  double t = p.cwiseQuotient(radii).squaredNorm() < 1.0 ? 0.0 : radii.maxCoeff() * p.norm();
  for (int step = 0; step < kMaxNewtonSteps; ++step) {
    const double P = t + r2[0], Q = t + r2[1], R = t + r2[2];
    const double f =
        P * P * Q * Q * R * R - r2p2[0] * Q * Q * R * R - r2p2[1] * P * P * R * R -
        r2p2[2] * P * P * Q * Q;
    if (std::abs(f) < kResidual) {
      return {r2[0] * p[0] / P, r2[1] * p[1] / Q, r2[2] * p[2] / R};
    }
    const double PQ = P * Q, PR = P * R, QR = Q * R;
    const double df = 2.0 * (PQ * R * (QR + PR + PQ) - r2p2[0] * QR * (Q + R) -
                             r2p2[1] * PR * (P + R) - r2p2[2] * PQ * (P + Q));
    t -= f / df;
  }
  return fallback;
}

}  // namespace sinew::paths

#include <sinew/paths/ellipsoid_tangent_point.h>
#include <sinew/paths/unit_vector.h>

#include <cmath>
#include <limits>

namespace sinew::paths {
namespace {

using Vec4 = Eigen::Vector4d;
using Mat4 = Eigen::Matrix4d;

// OpenSim's constants: when P is on the surface; when to stop; the step limits.
constexpr double kOnSurface = 1e-4;
constexpr double kConverged = 1e-8;
constexpr int kMaxSteps = 50;
constexpr int kMaxInnerSteps = 1000;

// The residuals at r with tangent-plane offset d1: r in the plane; r on the ellipsoid; the
// tangent plane g . x + d1 = 0 (g = 2 r / radii^2, the gradient) through r, and through p.
struct Residuals {
  const Vec3& inverse_squared;  // 1 / radii^2
  const Vec3& p;
  const Vec3& n;
  double d;
  Vec4 operator()(const Vec3& r, double d1) const {
    const Vec3 g = 2.0 * r.cwiseProduct(inverse_squared);
    return {n.dot(r) + d, r.cwiseProduct(r).dot(inverse_squared) - 1.0, g.dot(r) + d1,
            g.dot(p) + d1};
  }
};

}  // namespace

void SolveEllipsoidTangentPoint(const Vec3& radii, const Vec3& p, double p_level, const Vec3& n,
                                double d, Vec3& r) {
  if (std::abs(p_level) < kOnSurface) {
    r = p;
    return;
  }
  const Vec3 inverse_squared = radii.cwiseProduct(radii).cwiseInverse();
  const Residuals residuals{inverse_squared, p, n, d};
  double d1 = -2.0 * r.cwiseProduct(r).dot(inverse_squared);
  Vec4 e = residuals(r, d1);
  double ssq = e.squaredNorm(), ssq_before = ssq;
  double damping = 0.01;
  for (int step = 0; step < kMaxSteps && ssq > kConverged; ++step) {
    // Transposed Jacobian: row k is d(residuals)/d(unknown k), unknowns r_x, r_y, r_z, d1.
    Mat4 Jt;
    for (int i = 0; i < 3; ++i) {
      Jt.row(i) << n[i], 2.0 * r[i] * inverse_squared[i], 4.0 * r[i] * inverse_squared[i],
          2.0 * p[i] * inverse_squared[i];
    }
    Jt.row(3) << 0.0, 0.0, 1.0, 1.0;
    // Steps shrink as r nears P's radial direction (where the tangent point is ill-posed).
    const double cosine = NormalizedOrZero(p - r).dot(NormalizedOrZero(p));
    const double shrink = cosine > 0.1 ? 1.0 - std::pow(cosine, 100) : 1.0;
    const Vec4 descent = -Jt * e;
    Mat4 normal = Jt * Jt.transpose();
    const Vec4 diagonal = normal.diagonal();
    // Damped steps, accumulated, the damping growing fourfold, until the residual drops.
    Vec4 delta = Vec4::Zero();
    for (int inner = 0; inner < kMaxInnerSteps && ssq >= ssq_before; ++inner) {
      normal.diagonal() = diagonal * (1.0 + damping);
      delta = shrink * (normal.inverse() * descent) / 16.0;
      r += delta.head<3>();
      d1 += delta[3];
      e = residuals(r, d1);
      ssq_before = ssq;
      ssq = e.squaredNorm();
      damping *= 4.0;
    }
    damping /= 8.0;
    // Then further along the last step, doubling, while the residual keeps dropping; the
    // last move (which did not help) is undone.
    double factor = 0.5;
    for (int inner = 0; inner < kMaxInnerSteps && ssq <= ssq_before; ++inner) {
      factor *= 2.0;
      r += factor * delta.head<3>();
      d1 += factor * delta[3];
      e = residuals(r, d1);
      ssq_before = ssq;
      ssq = e.squaredNorm();
    }
    r -= factor * delta.head<3>();
    d1 -= factor * delta[3];
    e = residuals(r, d1);
    ssq = e.squaredNorm();
    ssq_before = ssq;
  }
}

}  // namespace sinew::paths
